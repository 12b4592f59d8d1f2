#include "viz/plan_symbols.hpp"

#include <algorithm>
#include <cmath>

#include "viz/polygon2d.hpp"

namespace penumbra::viz {

namespace {

// A face seen edge-on projects to almost nothing: less than 1 % of its own area.
PlotPolygon projected(const std::vector<Vec3>& vertices, double ownArea, const PlotPlane& plot) {
  PlotPolygon points;
  for (const Vec3& v : vertices) points.push_back(plot.project(v));
  PlotPolygon hull = convexHull(points);
  if (hull.size() < 3 || std::abs(signedArea(hull)) < 0.01 * ownArea) return {};
  return hull;
}

}  // namespace

std::vector<PlotPolygon> projectedOpenings(const Scene& scene, const PlotPlane& plot) {
  std::vector<PlotPolygon> openings;
  if (!scene.room) return openings;
  for (const Opening& opening : scene.room->openings) {
    std::vector<Vec3> corners = opening.inner.vertices();
    corners.insert(corners.end(), opening.outer.vertices().begin(), opening.outer.vertices().end());
    // Measured against the hole's side, so that a plan (the hole seen from above) keeps it.
    const double thickness = (opening.outer.centroid() - opening.inner.centroid()).norm();
    const double side = std::sqrt(opening.inner.area());
    PlotPolygon outline =
        projected(corners, std::min(opening.inner.area(), thickness * side), plot);
    if (!outline.empty()) openings.push_back(std::move(outline));
  }
  return openings;
}

std::vector<PlotPolygon> projectedLuminaires(const Scene& scene, const PlotPlane& plot) {
  std::vector<PlotPolygon> luminaires;
  for (const Source& source : scene.sources) {
    for (const ConvexPolygon& face : source.faces) {
      PlotPolygon outline = projected(face.vertices(), face.area(), plot);
      if (!outline.empty()) luminaires.push_back(std::move(outline));
    }
  }
  return luminaires;
}

}  // namespace penumbra::viz
