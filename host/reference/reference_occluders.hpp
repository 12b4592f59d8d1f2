#pragma once
// The solids as the reference estimators' visibility tests see them (reference_illuminance.cpp,
// luminaire_illuminance.cpp): face planes as structure of arrays, each plane's offset moved
// inwards by the scene tolerance, so that touching and grazing never block.
#include <vector>

#include "geometry/vec.hpp"
#include "scene/scene.hpp"

namespace penumbra::reference {

struct Occluder {
  int solid = -1;  // index into Scene::solids
  std::vector<Vec3> normals;
  std::vector<double> shrunkOffsets;
  std::vector<Vec3> vertices;
  Vec3 lo, hi;  // bounding box
};

// Every non-empty solid of `scene`, its planes moved inwards by `tolerance` (m).
std::vector<Occluder> buildOccluders(const Scene& scene, double tolerance);

// Cyrus–Beck: whether the open segment from `p` to `q` runs through the occluder's shrunk
// interior for longer than `tolerance`.
bool segmentBlocked(const Occluder& occluder, const Vec3& p, const Vec3& q, double tolerance);

}  // namespace penumbra::reference
