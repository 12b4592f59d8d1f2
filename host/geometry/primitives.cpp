#include "geometry/primitives.hpp"

#include <cmath>
#include <numbers>

namespace penumbra {

std::pair<Vec3, Vec3> frameAround(const Vec3& axis, const Vec3& preferred) {
  Vec3 u = preferred - preferred.dot(axis) * axis;
  // The light along the axis: L_E is "an arbitrary vector perpendicular" (paper, appendix).
  if (u.norm() < 1e-9) {
    u = std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    u -= u.dot(axis) * axis;
  }
  u.normalize();
  return {u, axis.cross(u)};
}

ConvexPolyhedron tessellate(const SphereShape& sphere, int facets, const Vec3& light,
                            FacetPlacement placement, double tolerance) {
  const double pi = std::numbers::pi;
  const Vec3 north = light.normalized();
  // Named, not a structured binding: clang 14 (the fuzz build) cannot capture those in a lambda.
  const std::pair<Vec3, Vec3> frame = frameAround(north, Vec3::UnitX());
  const Vec3 u = frame.first, v = frame.second;
  const int n = facets, around = 2 * facets;
  std::vector<Vec3> points;
  const auto ring = [&](double polar) {
    for (int j = 0; j < around; ++j) {
      const double azimuth = 2.0 * pi * j / around;
      const Vec3 d = std::cos(polar) * north +
                     std::sin(polar) * (std::cos(azimuth) * u + std::sin(azimuth) * v);
      points.push_back(sphere.center + sphere.radius * d);
    }
  };
  if (placement == FacetPlacement::Laminae) {
    points.push_back(sphere.center + sphere.radius * north);
    points.push_back(sphere.center - sphere.radius * north);
    for (int i = 1; i < n; ++i) ring(pi * i / n);
  } else {
    // Half a step turned: rings at (i + ½)π/N, flat caps facing the light and away from it.
    for (int i = 0; i < n; ++i) ring(pi * (i + 0.5) / n);
  }
  return ConvexPolyhedron::hull(points, tolerance);
}

ConvexPolyhedron tessellate(const TruncusShape& truncus, int facets, const Vec3& light,
                            FacetPlacement placement, double tolerance) {
  const double pi = std::numbers::pi;
  const double height = truncus.axis.norm();
  const Vec3 a = truncus.axis / height;
  const std::pair<Vec3, Vec3> frame = frameAround(a, light);  // L_En and L_En × a (up to sign)
  const Vec3 le = frame.first, side = frame.second;
  const double offset = placement == FacetPlacement::Laminae ? 0.0 : 0.5;
  std::vector<Vec3> points;
  const auto rim = [&](const Vec3& centre, double radius) {
    if (radius <= 0.0) {
      points.push_back(centre);  // a cone's apex
      return;
    }
    for (int j = 0; j < facets; ++j) {
      const double angle = 2.0 * pi * (j + offset) / facets;
      points.push_back(centre + radius * (std::cos(angle) * le + std::sin(angle) * side));
    }
  };
  rim(truncus.center + 0.5 * truncus.axis, truncus.r1);
  rim(truncus.center - 0.5 * truncus.axis, truncus.r2);
  return ConvexPolyhedron::hull(points, tolerance);
}

}  // namespace penumbra
