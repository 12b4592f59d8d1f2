#pragma once
// Small scenes built by hand (no loader), shared by the kernel and reference tests.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "geometry/convex_polyhedron.hpp"
#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra::testing {

// An area source from vertices listed counter-clockwise about the emission direction.
inline Source areaSource(std::vector<Vec3> vertices, double luminance, std::string name = "src") {
  Source s;
  s.name = std::move(name);
  s.faces.push_back(ConvexPolygon(std::move(vertices)));
  s.luminance = luminance;
  return s;
}

// Axis-aligned rectangle in the plane z = height, emitting downwards (-z).
inline Source ceilingRect(double x0, double y0, double x1, double y1, double height,
                          double luminance) {
  // Counter-clockwise about -z: clockwise seen from above.
  return areaSource({{x0, y0, height}, {x0, y1, height}, {x1, y1, height}, {x1, y0, height}},
                    luminance);
}

inline Solid boxSolid(const Vec3& min, const Vec3& max, std::string name = "box") {
  return Solid{std::move(name), ConvexPolyhedron::box(min, max), -1};
}

inline Source regularPolygonSource(int sides, double radius, double height, double luminance) {
  std::vector<Vec3> v;
  for (int i = 0; i < sides; ++i) {
    // Clockwise seen from above, so counter-clockwise about the emission direction -z.
    const double a = -2.0 * std::numbers::pi * i / sides;
    v.emplace_back(radius * std::cos(a), radius * std::sin(a), height);
  }
  return areaSource(std::move(v), luminance);
}

inline std::vector<SamplePoint> floorLine(double x0, double x1, int count, double y = 0.0,
                                          double z = 0.0, int solid = -1) {
  std::vector<SamplePoint> points;
  for (int i = 0; i < count; ++i) {
    const double x = count == 1 ? x0 : x0 + (x1 - x0) * i / (count - 1);
    points.push_back({Vec3(x, y, z), Vec3::UnitZ(), solid});
  }
  return points;
}

// Configuration factor, differential element to a parallel rectangle a × b at distance c with
// a corner over the element (catalogue formula; E = π·L·F).
inline double parallelCornerFactor(double a, double b, double c) {
  const double x = a / c, y = b / c;
  const double sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
  return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2 * std::numbers::pi);
}

// Differential element at the origin in the plane z = 0 (normal +z) to the rectangle
// 0 <= x <= a, 0 <= z <= c in the plane y = b (perpendicular, one edge on the element's plane).
inline double perpendicularFactor(double a, double b, double c) {
  const double d = std::sqrt(b * b + c * c);
  return (std::atan(a / b) - b / d * std::atan(a / d)) / (2 * std::numbers::pi);
}

}  // namespace penumbra::testing
