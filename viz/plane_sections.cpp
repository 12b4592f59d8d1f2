#include "viz/plane_sections.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/tolerance.hpp"
#include "viz/polygon2d.hpp"

namespace penumbra::viz {

namespace {

// Two unit vectors in the plane, e1 × e2 = normal.
std::pair<Vec3, Vec3> planeAxes(const Plane& plane) {
  const Vec3 e1 = (std::abs(plane.normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY())
                      .cross(plane.normal)
                      .normalized();
  return {e1, plane.normal.cross(e1)};
}

// Orders points of a convex planar polygon around their centroid (counter-clockwise about the
// plane's normal) and drops repeats (a vertex on the plane is met by several edges).
std::vector<Vec3> convexLoop(std::vector<Vec3> points, const Plane& plane, double tolerance) {
  if (points.size() < 3) return {};
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : points) centre += p;
  centre /= static_cast<double>(points.size());
  // Not a structured binding: clang 14 cannot capture one in the lambda below.
  const std::pair<Vec3, Vec3> axes = planeAxes(plane);
  const Vec3 e1 = axes.first, e2 = axes.second;
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

std::vector<Vec3> footprintOf(const ConvexPolyhedron& solid, const Plane& plane, double tolerance) {
  if (solid.empty()) return {};
  const auto [e1, e2] = planeAxes(plane);
  Polygon2 projected;
  for (const Vec3& v : solid.vertices()) {
    if (plane.signedDistance(v) <= tolerance) return {};  // reaches the plane or lies behind it
    projected.emplace_back(v.dot(e1), v.dot(e2));
  }
  const Polygon2 hull = convexHull(std::move(projected));
  if (hull.size() < 3) return {};  // seen edge-on: a vertical sheet has no area over the plane
  std::vector<Vec3> footprint;  // (e1, e2, normal) is orthonormal: on the plane, v·normal = offset
  for (const Eigen::Vector2d& p : hull) {
    footprint.push_back(p.x() * e1 + p.y() * e2 + plane.offset * plane.normal);
  }
  return footprint;
}

std::vector<SolidSection> solidFootprints(const Scene& scene, const Plane& plane) {
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  std::vector<SolidSection> footprints;
  for (const Solid& solid : scene.solids) {
    if (solid.name.starts_with("room.")) continue;
    std::vector<Vec3> polygon = footprintOf(solid.shape, plane, tolerance);
    if (!polygon.empty()) footprints.push_back({solid.name, false, std::move(polygon)});
  }
  return footprints;
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
