#include "scene/shape_builder.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/primitives.hpp"

namespace penumbra::scenefile {
namespace {

Vec3 lightAt(const BuildContext& context, const Vec3& point) {
  return context.towardsLight ? context.towardsLight(point) : Vec3::UnitZ();
}

// The placement docs/primitives.md measured to be the better one.
constexpr FacetPlacement kFacetPlacement = FacetPlacement::Laminae;

ConvexPolyhedron buildSphere(const SphereSpec& s, const Where& where, const BuildContext& context) {
  ConvexPolyhedron shape =
      tessellate(SphereShape{s.center, s.radius}, s.facets, lightAt(context, s.center),
                 kFacetPlacement, context.tolerance);
  if (shape.empty()) context.fail(where, "the sphere is too small for the scene's tolerance");
  return shape;
}

ConvexPolyhedron buildTruncus(const TruncusSpec& t, const Where& where,
                              const BuildContext& context) {
  ConvexPolyhedron shape =
      tessellate(TruncusShape{t.center, t.axis, t.r1, t.r2}, t.facets, lightAt(context, t.center),
                 kFacetPlacement, context.tolerance);
  if (shape.empty()) {
    context.fail(where, "the shape has no volume at the scene's tolerance (radius or height)");
  }
  return shape;
}

ConvexPolyhedron buildBox(const BoxSpec& box, const Where& where, const BuildContext& context) {
  if (((box.max - box.min).array() <= context.tolerance).any()) {
    context.fail(where, "the box has no volume: max must be greater than min in x, y and z (min " +
                            formatVec3(box.min) + ", max " + formatVec3(box.max) + ")");
  }
  return ConvexPolyhedron::box(box.min, box.max);
}

ConvexPolyhedron buildPrism(const PrismSpec& prism, const BuildContext& context) {
  const ConvexPolygon base = validatedPolygon(prism.base, prism.baseWhere, context);
  // A base drawn on a floor plan extrudes upwards whichever way round its vertices are listed;
  // only a vertical base (a wall-like prism) has no "up" and follows its vertex order.
  Vec3 direction = base.normal();
  if (std::abs(direction.z()) > kInputAngleTolerance && direction.z() < 0.0) direction = -direction;
  ConvexPolyhedron shape =
      ConvexPolyhedron::prism(base, prism.height * direction, context.tolerance);
  if (shape.empty()) {
    context.fail(prism.baseWhere, "the prism has no volume: its height " +
                                      formatNumber(prism.height) + " m is below the tolerance");
  }
  return shape;
}

ConvexPolyhedron buildHull(const HullSpec& hull, const Where& where, const BuildContext& context) {
  ConvexPolyhedron shape = ConvexPolyhedron::hull(hull.points, context.tolerance);
  if (shape.empty()) {
    context.fail(where, "the hull has no volume: its points lie in one plane (or on one line)");
  }
  return shape;
}

}  // namespace

ConvexPolygon validatedPolygon(const std::vector<Vec3>& vertices, const Where& where,
                               const BuildContext& context) {
  const double tol = context.tolerance;
  const std::size_t n = vertices.size();
  double longestEdge = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double edge = (vertices[(i + 1) % n] - vertices[i]).norm();
    if (edge <= tol) {
      context.fail(where, "vertices " + std::to_string(i) + " and " + std::to_string((i + 1) % n) +
                              " (counting from 0) are the same point " + formatVec3(vertices[i]));
    }
    longestEdge = std::max(longestEdge, edge);
  }
  const ConvexPolygon polygon(vertices);
  // Thinner than the tolerance everywhere (area / longest edge bounds the width): no area.
  if (polygon.area() <= tol * longestEdge) {
    context.fail(where, "the polygon has zero area: its vertices lie on one line");
  }
  if (!polygon.isPlanar(tol)) {
    const Plane plane = polygon.plane();
    double off = 0.0;
    for (const Vec3& v : vertices) off = std::max(off, std::abs(plane.signedDistance(v)));
    context.fail(where, "the polygon is not planar: a vertex lies " + formatNumber(off) +
                            " m off the plane of the others (tolerance " + formatNumber(tol) +
                            " m)");
  }
  if (!polygon.isConvex(tol)) {
    context.fail(where,
                 "the polygon is not convex, or its vertices do not run in order around "
                 "its edge; split a concave shape into convex parts");
  }
  return polygon;
}

bool isPolyhedron(const ShapeSpec& shape) {
  return std::holds_alternative<BoxSpec>(shape) || std::holds_alternative<PrismSpec>(shape) ||
         std::holds_alternative<HullSpec>(shape) || std::holds_alternative<SphereSpec>(shape) ||
         std::holds_alternative<TruncusSpec>(shape);
}

ConvexPolyhedron buildPolyhedron(const ShapeSpec& shape, const Where& where,
                                 const BuildContext& context) {
  if (const auto* box = std::get_if<BoxSpec>(&shape)) return buildBox(*box, where, context);
  if (const auto* prism = std::get_if<PrismSpec>(&shape)) return buildPrism(*prism, context);
  if (const auto* hull = std::get_if<HullSpec>(&shape)) return buildHull(*hull, where, context);
  if (const auto* sphere = std::get_if<SphereSpec>(&shape))
    return buildSphere(*sphere, where, context);
  if (const auto* truncus = std::get_if<TruncusSpec>(&shape))
    return buildTruncus(*truncus, where, context);
  throw std::logic_error("buildPolyhedron: not a polyhedron shape");
}

}  // namespace penumbra::scenefile
