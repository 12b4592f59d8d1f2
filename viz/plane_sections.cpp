#include "viz/plane_sections.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/tolerance.hpp"

namespace penumbra::viz {

namespace {

// Orders points of a convex planar polygon around their centroid (counter-clockwise about the
// plane's normal) and drops repeats (a vertex on the plane is met by several edges).
std::vector<Vec3> convexLoop(std::vector<Vec3> points, const Plane& plane, double tolerance) {
  if (points.size() < 3) return {};
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : points) centre += p;
  centre /= static_cast<double>(points.size());
  const Vec3 e1 = (std::abs(plane.normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY())
                      .cross(plane.normal)
                      .normalized();
  const Vec3 e2 = plane.normal.cross(e1);
  const auto angle = [&](const Vec3& p) {
    return std::atan2((p - centre).dot(e2), (p - centre).dot(e1));
  };
  std::sort(points.begin(), points.end(),
            [&](const Vec3& a, const Vec3& b) { return angle(a) < angle(b); });
  std::vector<Vec3> loop;
  for (const Vec3& p : points) {
    if (loop.empty() || (p - loop.back()).norm() > tolerance) loop.push_back(p);
  }
  while (loop.size() > 1 && (loop.front() - loop.back()).norm() <= tolerance) loop.pop_back();
  if (loop.size() < 3) return {};
  return loop;
}

}  // namespace

std::vector<Vec3> sectionOf(const ConvexPolyhedron& solid, const Plane& plane, double tolerance) {
  if (solid.empty()) return {};
  const auto& vertices = solid.vertices();
  std::vector<double> distance;
  distance.reserve(vertices.size());
  for (const Vec3& v : vertices) distance.push_back(plane.signedDistance(v));
  const auto [lowest, highest] = std::minmax_element(distance.begin(), distance.end());
  // Nothing on the front side, or not reaching the plane.
  if (*highest <= tolerance || *lowest > tolerance) return {};

  std::vector<Vec3> points;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (std::abs(distance[i]) <= tolerance) points.push_back(vertices[i]);
  }
  for (const ConvexPolyhedron::Edge& edge : solid.edges()) {
    const double d0 = distance[edge.from], d1 = distance[edge.to];
    if ((d0 < -tolerance && d1 > tolerance) || (d0 > tolerance && d1 < -tolerance)) {
      const double t = d0 / (d0 - d1);
      points.push_back(vertices[edge.from] + t * (vertices[edge.to] - vertices[edge.from]));
    }
  }
  return convexLoop(std::move(points), plane, tolerance);
}

std::vector<SolidSection> solidSections(const Scene& scene, const Plane& plane) {
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  std::vector<SolidSection> sections;
  for (const Solid& solid : scene.solids) {
    std::vector<Vec3> polygon = sectionOf(solid.shape, plane, tolerance);
    if (polygon.empty()) continue;
    sections.push_back({solid.name, solid.name.starts_with("room."), std::move(polygon)});
  }
  return sections;
}

std::vector<Vec3> roomOutline(const Scene& scene, const Plane& plane) {
  if (!scene.room) return {};
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  return sectionOf(ConvexPolyhedron::box(Vec3::Zero(), scene.room->size), plane, tolerance);
}

}  // namespace penumbra::viz
