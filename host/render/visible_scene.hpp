#pragma once
// What a camera can see, packed for kernels/visibility.cl: every solid (a plane set) and every
// source (a polygon, or a polyhedron given by its emitting faces), and the table that turns a
// face id back into the face it names.
//
// Face ids: 0 is "nothing"; the faces of scene.solids come first, in order (solid 0's faces
// 1..F0, then solid 1's, ...), then the faces of scene.sources in order. The same numbering is
// written to <view>.faceid.exr.
#include <vector>

#include "geometry/plane.hpp"
#include "kernels/shared_types.h"
#include "scene/scene.hpp"

namespace penumbra {

struct VisibleFace {
  bool isSource = false;
  int index = -1;  // into scene.solids or scene.sources
  int face = -1;   // the solid's face, or the source's face
  Plane plane;     // outward (solids) or emitting (sources)
};

struct VisibleScene {
  std::vector<PnVisibleObject> objects;  // solids, then sources
  // In scene coordinates, in double: the engine packs them relative to each camera's eye.
  std::vector<Plane> planes;
  std::vector<VisibleFace> faces;  // faces[id - 1]
  // Per object: its vertices and its edges (pairs of indices into them), to bin it into the
  // screen tiles it may cover.
  std::vector<std::vector<Vec3>> vertices;
  std::vector<std::vector<std::pair<int, int>>> edges;

  const VisibleFace& face(uint32_t id) const { return faces[id - 1]; }
};

VisibleScene buildVisibleScene(const Scene& scene);

}  // namespace penumbra
