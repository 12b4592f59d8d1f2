#include "reference/region_solid_angle.hpp"

#include <cmath>

namespace penumbra {

double triangleSolidAngle(const Vec3& w, const Vec3& a, const Vec3& b) {
  return 2.0 * std::atan2(w.dot(b.cross(a)), 1.0 + w.dot(a) + a.dot(b) + w.dot(b));
}

double regionSolidAngle(std::span<const VisibleArc> arcs, const Vec3& w) {
  double sum = 0.0;
  for (const VisibleArc& arc : arcs) {
    const Vec3 a = arc.from.normalized(), b = arc.to.normalized();
    if (b.cross(a).norm() == 0.0) continue;
    sum += triangleSolidAngle(w, a, b);
  }
  return sum;
}

}  // namespace penumbra
