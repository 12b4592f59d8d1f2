#include "illuminance/far_polygon.hpp"

#include "reference/cosine_moments.hpp"
#include "reference/visible_boundary.hpp"

namespace penumbra {

FarPlacement FarPlacement::of(const Scene& scene) {
  BoundingBox box;
  for (const Solid& solid : scene.solids)
    for (const Vec3& v : solid.shape.vertices()) box.add(v);
  FarPlacement placement;
  if ((box.lo.array() <= box.hi.array()).all()) {
    placement.centre = 0.5 * (box.lo + box.hi);
    placement.diagonal = (box.hi - box.lo).norm();
  }
  return placement;
}

double FarPlacement::distance(const Vec3& point) const {
  // Every solid vertex lies within |P − centre| + diagonal/2 of P: twice that and a metre is
  // beyond every solid.
  return 2.0 * ((point - centre).norm() + diagonal) + 1.0;
}

ConvexPolygon throughHole(const ConvexPolygon& far, const Vec3& p, const ConvexPolygon& hole) {
  const std::vector<Vec3>& v = hole.vertices();
  const Vec3 inside = hole.centroid() - p;
  ConvexPolygon part = far;
  for (std::size_t i = 0; i < v.size() && !part.empty(); ++i) {
    Vec3 m = (v[i] - p).cross(v[(i + 1) % v.size()] - p);
    if (m.norm() == 0.0) return {};  // p in the hole's plane: no direction passes through it
    m.normalize();
    if (m.dot(inside) > 0.0) m = -m;  // keep m·(x − p) <= 0, the side of the hole's inside
    part = part.clipped(Plane{m, m.dot(p)}, 0.0);
  }
  return part;
}

ConvexPolygon farImage(const ConvexPolygon& hole, const Vec3& p, double distance) {
  const double height = hole.plane().signedDistance(p);
  const double ratio = distance / height;
  std::vector<Vec3> vertices;
  vertices.reserve(hole.vertices().size());
  for (const Vec3& v : hole.vertices()) vertices.push_back(p + ratio * (v - p));
  return ConvexPolygon(std::move(vertices));
}

std::vector<double> visibleMoments(const ConvexPolygon& polygon, const SamplePoint& point,
                                   const Scene& scene, double tolerance, const Vec3& axis,
                                   int order) {
  std::vector<double> zeros(static_cast<std::size_t>(order) + 1, 0.0);
  if (polygon.empty() || !(polygon.area() > 0.0)) return zeros;
  const std::vector<VisibleArc> arcs =
      visibleBoundary(polygon, FaceFrame::of(polygon), point, scene, tolerance);
  if (arcs.empty()) return zeros;
  return cosineMoments(arcs, axis, point.normal.normalized(), order);
}

double visibleProjectedSolidAngle(const ConvexPolygon& polygon, const SamplePoint& point,
                                  const Scene& scene, double tolerance) {
  const Vec3 n = point.normal.normalized();
  return visibleMoments(polygon, point, scene, tolerance, n, 0).front();
}

}  // namespace penumbra
