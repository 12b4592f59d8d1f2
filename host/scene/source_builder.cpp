#include "scene/source_builder.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "scene/shape_builder.hpp"

namespace penumbra::scenefile {
namespace {

ConvexPolygon polygonFace(const PolygonSpec& spec, const Where& where,
                          const BuildContext& context) {
  const ConvexPolygon polygon = validatedPolygon(spec.vertices, where, context);
  if (!spec.normal) return polygon;  // emits along the right-hand normal of the vertex order
  const Vec3 own = polygon.normal();
  const double sine = spec.normal->cross(own).norm();
  if (sine > kInputAngleTolerance) {
    const double degrees = std::asin(std::min(sine, 1.0)) * 180.0 / std::numbers::pi;
    context.fail(spec.normalWhere, "the normal " + formatVec3(*spec.normal) +
                                       " is not perpendicular to the polygon (" +
                                       formatNumber(std::round(degrees * 10.0) / 10.0) +
                                       "° off); the polygon's plane has normal ±" +
                                       formatVec3(own));
  }
  // Stored counter-clockwise about the emission direction, whatever order was typed.
  return spec.normal->dot(own) < 0.0 ? polygon.reversed() : polygon;
}

ConvexPolygon openingFace(const OpeningRefSpec& spec, const Where& where,
                          const std::optional<Room>& room, const BuildContext& context) {
  if (!room) {
    context.fail(where,
                 "an 'opening:' source fills an opening of the room, but the scene has no "
                 "'room:'");
  }
  std::string names;
  for (const Opening& opening : room->openings) {
    // Both polygons already face into the room, the direction a window emits to.
    if (opening.name == spec.opening) return spec.outerPlane ? opening.outer : opening.inner;
    names += (names.empty() ? "" : ", ") + opening.name;
  }
  context.fail(where,
               "unknown opening '" + spec.opening + "'; " +
                   (names.empty() ? "the room has no openings" : "the room's openings: " + names));
}

}  // namespace

ConvexPolygon rectPolygon(const Vec3& center, double width, double height, const Vec3& normal) {
  const Vec3 n = normal.normalized();
  // Near the x axis the projection of +x is short and swings with tiny changes of the normal;
  // +y is then the stable choice.
  const Vec3 reference =
      n.cross(Vec3::UnitX()).norm() < kInputAngleTolerance ? Vec3::UnitY() : Vec3::UnitX();
  const Vec3 u = (reference - reference.dot(n) * n).normalized();
  const Vec3 v = n.cross(u);  // (u, v, n) right-handed: u → v turns counter-clockwise about n
  const Vec3 a = 0.5 * width * u;
  const Vec3 b = 0.5 * height * v;
  return ConvexPolygon({center - a - b, center + a - b, center + a + b, center - a + b});
}

Source buildSource(const SourceSpec& spec, const std::optional<Room>& room,
                   const BuildContext& context) {
  Source source;
  source.name = spec.name;
  source.color = spec.color;
  if (isPolyhedron(spec.shape)) {
    const ConvexPolyhedron shape = buildPolyhedron(spec.shape, spec.shapeWhere, context);
    source.shape = SourceShape::Polyhedron;
    // Face loops run counter-clockwise seen from outside: each face emits outwards.
    for (int f = 0; f < static_cast<int>(shape.faces().size()); ++f) {
      source.faces.push_back(shape.facePolygon(f));
    }
  } else if (const auto* polygon = std::get_if<PolygonSpec>(&spec.shape)) {
    source.faces.push_back(polygonFace(*polygon, spec.shapeWhere, context));
  } else if (const auto* rect = std::get_if<RectSpec>(&spec.shape)) {
    source.faces.push_back(rectPolygon(rect->center, rect->width, rect->height, rect->normal));
  } else {
    const auto& opening = std::get<OpeningRefSpec>(spec.shape);
    source.faces.push_back(openingFace(opening, spec.shapeWhere, room, context));
    source.opening = opening.opening;
  }
  // A Lambertian emitter of luminance L and area A sends Φ = π·L·A.
  source.luminance =
      spec.luminance ? *spec.luminance : *spec.flux / (std::numbers::pi * source.emittingArea());
  // An opening's glazing passes τ of what the source behind it sends.
  if (!source.opening.empty())
    for (const Opening& o : room->openings)
      if (o.name == source.opening) source.luminance *= o.transmittance;
  return source;
}

}  // namespace penumbra::scenefile
