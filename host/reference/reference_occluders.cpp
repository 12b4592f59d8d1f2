#include "reference/reference_occluders.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra::reference {

std::vector<Occluder> buildOccluders(const Scene& scene, double tolerance) {
  std::vector<Occluder> occluders;
  for (int s = 0; s < static_cast<int>(scene.solids.size()); ++s) {
    const ConvexPolyhedron& shape = scene.solids[s].shape;
    if (shape.empty()) continue;
    Occluder o;
    o.solid = s;
    for (const auto& face : shape.faces()) {
      o.normals.push_back(face.plane.normal);
      o.shrunkOffsets.push_back(face.plane.offset - tolerance);
    }
    o.vertices = shape.vertices();
    o.lo = o.hi = o.vertices.front();
    for (const Vec3& p : o.vertices) {
      o.lo = o.lo.cwiseMin(p);
      o.hi = o.hi.cwiseMax(p);
    }
    occluders.push_back(std::move(o));
  }
  return occluders;
}

bool segmentBlocked(const Occluder& o, const Vec3& p, const Vec3& q, double tolerance) {
  for (int axis = 0; axis < 3; ++axis) {
    if (std::max(p[axis], q[axis]) < o.lo[axis] || std::min(p[axis], q[axis]) > o.hi[axis]) {
      return false;
    }
  }
  const Vec3 w = q - p;
  double enter = 0.0, leave = 1.0;
  for (std::size_t k = 0; k < o.normals.size(); ++k) {
    const double height = o.normals[k].dot(p) - o.shrunkOffsets[k];  // < 0 inside
    const double rate = o.normals[k].dot(w);
    if (rate == 0.0) {
      if (height >= 0.0) return false;
      continue;
    }
    const double t = -height / rate;
    if (rate > 0.0) {
      leave = std::min(leave, t);
    } else {
      enter = std::max(enter, t);
    }
    if (enter >= leave) return false;
  }
  return (leave - enter) * w.norm() > tolerance;
}

}  // namespace penumbra::reference
