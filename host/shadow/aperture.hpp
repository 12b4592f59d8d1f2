#pragma once
// Apertures (docs/method.md, "Apertures"): a source face that fills an opening of the room on the
// wall's outer plane (a window's sky, `opening:` sources by default) is seen from inside the room
// only through the opening's room-side polygon A. For a point P strictly in front of A's plane
// and inside the room, a segment P→x (x on the face) misses the wall slabs iff it crosses A's
// plane inside A: elsewhere on that plane it enters a slab, or another opening whose tunnel is
// separated from the face's by wall. So for such points the visible source is the face ∩ cone(P,
// A), and every solid in the closed back half-space of A's plane and outside the open prism
// conv(A ∪ face) (the slabs around the opening) can be skipped as an occluder. Exact, not a
// sampling: the only approximation is the named length tolerance of the host checks.
//
// Only built when it is provably valid for the scene as it is: the face and A are parallel
// rectangles on axis-aligned planes, every opening in A's plane is a rectangle kept apart from
// the others, and the room-side face of the wall, minus those openings, is covered by box solids
// spanning the wall's whole thickness (what the room builder makes). Otherwise: no aperture.
#include <array>
#include <optional>

#include "geometry/bounding_box.hpp"
#include "geometry/tolerance.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct Aperture {
  Plane plane;  // A's plane, normal into the room (the face's emission direction)
  double sourceDepth =
      0.0;           // the face's plane: normal·x on it (plane.offset − the wall's thickness)
  BoundingBox room;  // the room's interior: points outside this closed box do not use A
  // Frame on the face's plane: axisU × axisV = the emission direction; rectangles as
  // (u0, u1, v0, v1) with u = x·axisU, v = x·axisV.
  Vec3 axisU = Vec3::UnitX(), axisV = Vec3::UnitY();
  std::array<double, 4> sourceRect{}, openingRect{};
};

// The aperture of an emitting face of `scene`, when it has one (see above).
std::optional<Aperture> findAperture(const Scene& scene, const ConvexPolygon& face,
                                     const Tolerance& tolerance);

// Whether an occluder (a solid clipped to the face's front half-space) cannot shade the face
// through the aperture: it lies in the closed back half-space of A's plane and outside the open
// prism conv(A ∪ face), tested conservatively (outside the prism's axis-aligned bounding prism).
bool behindAperture(const Aperture& aperture, const ConvexPolyhedron& occluder,
                    const Tolerance& tolerance);

}  // namespace penumbra
