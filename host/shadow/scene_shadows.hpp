#pragma once
// The shadow geometry of a scene, built once on the host (Nishita §2.1-2.4): for every emitting
// face, every solid clipped to that face's front half-space (Nishita: "the portion of the
// positive-space of S_e"; a ceiling slab around a flush panel becomes empty or thin) with its
// umbra and penumbra volumes. Solids left with no volume cast nothing and are dropped.
// A polyhedron source is handled face by face (the kernel integrates it so; docs/method.md).
#include <functional>
#include <optional>
#include <vector>

#include "geometry/tolerance.hpp"
#include "scene/scene.hpp"
#include "shadow/aperture.hpp"
#include "shadow/shadow_volume.hpp"

namespace penumbra {

struct ShadowCaster {
  int solid = -1;          // index into Scene::solids
  ConvexPolyhedron shape;  // the solid clipped to the face's front half-space
  ShadowVolume volume;
  bool behindAperture = false;  // skipped for points that see the face through its aperture
};

struct EmittingFaceShadows {
  int source = -1;  // index into Scene::sources
  ConvexPolygon face;
  std::vector<ShadowCaster> casters;
  std::optional<Aperture> aperture;  // a window's sky seen through the opening (aperture.hpp)
  // The face (index into SceneShadows::faces, an earlier one) whose casters serve this face, or
  // -1 for its own (Source::castersOf). A face inside another, in its plane, can share them: the
  // solids clipped to the same front half-space are the same, a smaller source's penumbra
  // volume lies inside the larger's and its umbra holds the larger's, and a plane that separates
  // the larger face from a solid separates the smaller one too; so the shared volumes only
  // cull less tightly, and the kernel's integral over the candidates stays exact. The element
  // trees' nodes share their ancestor's: a tree of thousands of nodes over a room of hundreds of
  // solids builds its pieces' casters, not every node's.
  int casterOwner = -1;
  bool emits = true;  // false for a source's face that only holds casters (Source::castersOnly)
  std::size_t casterFace(std::size_t self) const {
    return casterOwner < 0 ? self : static_cast<std::size_t>(casterOwner);
  }
};

struct SceneShadows {
  Tolerance tolerance;
  std::vector<EmittingFaceShadows> faces;  // every face of every source, in scene order
};

SceneShadows buildSceneShadows(const Scene& scene);
// The same, handing each face to `consume` as soon as its casters are built, in face order; what
// `consume` leaves of the face's casters is what the result holds (the kernel's engine packs
// them and clears them: a scene of thousands of faces never holds all its casters at once).
SceneShadows buildSceneShadows(const Scene& scene,
                               const std::function<void(EmittingFaceShadows&)>& consume);

}  // namespace penumbra
