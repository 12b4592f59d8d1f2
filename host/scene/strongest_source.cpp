#include "scene/strongest_source.hpp"

namespace penumbra {

Vec3 towardsStrongestSource(const std::vector<Source>& sources, const Vec3& point) {
  double best = 0.0;
  Vec3 direction = Vec3::UnitZ();
  for (const Source& source : sources) {
    double strength = 0.0;
    Vec3 weighted = Vec3::Zero();
    for (const ConvexPolygon& face : source.faces) {
      const Vec3 toPoint = point - face.centroid();
      const double d2 = toPoint.squaredNorm();
      const double cosine = d2 > 0.0 ? face.normal().dot(toPoint) / std::sqrt(d2) : 0.0;
      if (cosine <= 0.0) continue;  // the face emits away from the point
      const double e = source.luminance * face.area() * cosine / d2;
      strength += e;
      weighted += e * face.centroid();
    }
    if (strength > best) {
      best = strength;
      direction = (weighted / strength - point).normalized();
    }
  }
  return direction;
}

}  // namespace penumbra
