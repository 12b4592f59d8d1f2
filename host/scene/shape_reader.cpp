#include "scene/shape_reader.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

namespace penumbra::scenefile {
namespace {

const std::vector<std::string_view>& shapeKeys(ShapeUse use) {
  static const std::vector<std::string_view> solid{"box",      "prism", "hull",   "sphere",
                                                   "cylinder", "cone",  "truncus"};
  static const std::vector<std::string_view> source{"opening", "rect",   "polygon", "box",
                                                    "prism",   "hull",   "sphere",  "cylinder",
                                                    "cone",    "truncus"};
  return use == ShapeUse::Solid ? solid : source;
}

std::string listed(const std::vector<std::string_view>& words) {
  std::string out;
  for (std::string_view w : words) out += (out.empty() ? "" : ", ") + std::string(w);
  return out;
}

BoxSpec readBox(const Reader& reader, const Field& field) {
  const MapView box = reader.map(field, "a box {min: [x, y, z], max: [x, y, z]}");
  box.allowOnly({"min", "max"}, "a box");
  return BoxSpec{reader.vec3(box.require("min")), reader.vec3(box.require("max"))};
}

PrismSpec readPrism(const Reader& reader, const Field& field) {
  const MapView prism = reader.map(field, "a prism {base: [[x, y, z], ...], height: h}");
  prism.allowOnly({"base", "height"}, "a prism");
  const Field base = prism.require("base");
  return PrismSpec{reader.points(base, 3), reader.positive(prism.require("height"), "m"),
                   base.where};
}

RectSpec readRect(const Reader& reader, const Field& field) {
  const MapView rect =
      reader.map(field, "a rectangle {center: [x, y, z], size: [w, h], normal: [x, y, z]}");
  rect.allowOnly({"center", "size", "normal"}, "a source rectangle");
  RectSpec spec;
  spec.center = reader.vec3(rect.require("center"));
  const Field size = rect.require("size");
  const std::vector<double> wh = reader.numbers(size, 2);
  if (wh[0] <= 0.0 || wh[1] <= 0.0) {
    reader.fail(size.where, "a rectangle's width and height must be greater than 0 (got " +
                                formatNumber(wh[0]) + " × " + formatNumber(wh[1]) + " m)");
  }
  spec.width = wh[0];
  spec.height = wh[1];
  spec.normal = reader.direction(rect.require("normal"));
  return spec;
}

PolygonSpec readPolygon(const Reader& reader, const MapView& entry, const Field& field) {
  PolygonSpec spec;
  spec.vertices = reader.points(field, 3);
  if (const std::optional<Field> normal = entry.find("normal")) {
    spec.normal = reader.direction(*normal);
    spec.normalWhere = normal->where;
  }
  return spec;
}

OpeningRefSpec readOpeningRef(const Reader& reader, const MapView& entry, const Field& field) {
  OpeningRefSpec spec;
  spec.opening = reader.text(field);
  if (const std::optional<Field> plane = entry.find("plane")) {
    const std::string which = reader.text(*plane);
    if (which != "outer" && which != "inner") {
      reader.fail(plane->where,
                  "expected 'outer' (the wall's outside face, the default) or "
                  "'inner' (its room-side face), got '" +
                      which + "'");
    }
    spec.outerPlane = which == "outer";
  }
  return spec;
}

// `facets: N`, a whole number; kDefaultFacets when absent.
int readFacets(const Reader& reader, const MapView& map, int minimum) {
  const std::optional<Field> field = map.find("facets");
  if (!field) return kDefaultFacets;
  const double n = reader.number(*field);
  if (n != std::floor(n) || n < minimum || n > kMaxFacets) {
    reader.fail(field->where, "facets is a whole number from " + std::to_string(minimum) + " to " +
                                  std::to_string(kMaxFacets) + ", got " + formatNumber(n));
  }
  return static_cast<int>(n);
}

Vec3 readAxis(const Reader& reader, const MapView& map) {
  const Field field = map.require("axis");
  const Vec3 axis = reader.vec3(field);
  if (axis.norm() <= 0.0) {
    reader.fail(field.where, "the axis gives the direction and the height; it cannot be zero");
  }
  return axis;
}

SphereSpec readSphere(const Reader& reader, const Field& field) {
  const MapView map = reader.map(field, "a sphere {center: [x, y, z], radius: r}");
  map.allowOnly({"center", "radius", "facets"}, "a sphere");
  return SphereSpec{reader.vec3(map.require("center")), reader.positive(map.require("radius"), "m"),
                    readFacets(reader, map, 2)};
}

// cylinder and cone take one `radius`; a truncus takes r1 (at center + axis/2) and r2.
TruncusSpec readTruncus(const Reader& reader, const Field& field, std::string_view kind) {
  const bool general = kind == "truncus";
  const std::string what = "a " + std::string(kind);
  const MapView map =
      reader.map(field, what + (general ? " {center: [x, y, z], axis: [x, y, z], r1: r, r2: r}"
                                        : " {center: [x, y, z], axis: [x, y, z], radius: r}"));
  if (general) {
    map.allowOnly({"center", "axis", "r1", "r2", "facets"}, what);
  } else {
    map.allowOnly({"center", "axis", "radius", "facets"}, what);
  }
  TruncusSpec spec;
  spec.center = reader.vec3(map.require("center"));
  spec.axis = readAxis(reader, map);
  if (general) {
    spec.r1 = reader.nonNegative(map.require("r1"), "m");
    const Field r2 = map.require("r2");
    spec.r2 = reader.nonNegative(r2, "m");
    if (spec.r1 == 0.0 && spec.r2 == 0.0) {
      reader.fail(r2.where, "a truncus needs at least one radius greater than 0");
    }
  } else {
    const double radius = reader.positive(map.require("radius"), "m");
    spec.r1 = kind == "cone" ? 0.0 : radius;  // a cone's apex is at center + axis/2
    spec.r2 = radius;
  }
  spec.facets = readFacets(reader, map, 3);
  return spec;
}

}  // namespace

std::string_view shapeKeyOf(const Reader& reader, const MapView& entry, ShapeUse use,
                            std::string_view what, const std::vector<std::string_view>& otherKeys) {
  std::string_view found;
  for (std::string_view key : shapeKeys(use)) {
    if (!entry.has(key)) continue;
    if (!found.empty()) {
      reader.fail(entry.find(key)->where,
                  std::string(what) + " has one shape, but this one has both '" +
                      std::string(found) + "' and '" + std::string(key) + "'");
    }
    found = key;
  }
  if (found.empty()) {
    const std::string shapes =
        std::string(what) + " needs a shape: one of " + listed(shapeKeys(use));
    for (const MapView::Entry& e : entry.entries()) {
      if (std::find(otherKeys.begin(), otherKeys.end(), e.key) == otherKeys.end()) {
        reader.fail(e.value.where, "unknown key '" + e.key + "'; " + shapes);
      }
    }
    reader.fail(entry.where(), shapes);
  }
  return found;
}

std::vector<std::string_view> shapeSiblingKeys(std::string_view shapeKey) {
  if (shapeKey == "polygon") return {"normal"};
  if (shapeKey == "opening") return {"plane"};
  return {};
}

std::pair<ShapeSpec, Where> readShape(const Reader& reader, const MapView& entry,
                                      std::string_view shapeKey) {
  const Field field = entry.require(shapeKey);
  if (shapeKey == "box") return {readBox(reader, field), field.where};
  if (shapeKey == "prism") return {readPrism(reader, field), field.where};
  if (shapeKey == "hull") return {HullSpec{reader.points(field, 4)}, field.where};
  if (shapeKey == "rect") return {readRect(reader, field), field.where};
  if (shapeKey == "polygon") return {readPolygon(reader, entry, field), field.where};
  if (shapeKey == "sphere") return {readSphere(reader, field), field.where};
  if (shapeKey == "cylinder" || shapeKey == "cone" || shapeKey == "truncus")
    return {readTruncus(reader, field, shapeKey), field.where};
  return {readOpeningRef(reader, entry, field), field.where};
}

std::vector<Vec3> shapeExtentPoints(const ShapeSpec& shape) {
  struct Visitor {
    std::vector<Vec3> operator()(const BoxSpec& b) const { return {b.min, b.max}; }
    std::vector<Vec3> operator()(const PrismSpec& p) const {
      // The extrusion direction is decided later; a cube of side `height` around each base
      // vertex bounds the prism whichever way it goes.
      std::vector<Vec3> out;
      for (const Vec3& v : p.base) {
        out.push_back(v - Vec3::Constant(p.height));
        out.push_back(v + Vec3::Constant(p.height));
      }
      return out;
    }
    std::vector<Vec3> operator()(const HullSpec& h) const { return h.points; }
    std::vector<Vec3> operator()(const PolygonSpec& p) const { return p.vertices; }
    std::vector<Vec3> operator()(const RectSpec& r) const {
      const double half = 0.5 * std::hypot(r.width, r.height);
      return {r.center - Vec3::Constant(half), r.center + Vec3::Constant(half)};
    }
    std::vector<Vec3> operator()(const OpeningRefSpec&) const { return {}; }  // in the room
    std::vector<Vec3> operator()(const SphereSpec& s) const {
      return {s.center - Vec3::Constant(s.radius), s.center + Vec3::Constant(s.radius)};
    }
    std::vector<Vec3> operator()(const TruncusSpec& t) const {
      const Vec3 reach = Vec3::Constant(std::max(t.r1, t.r2));
      return {t.center + 0.5 * t.axis - reach, t.center + 0.5 * t.axis + reach,
              t.center - 0.5 * t.axis - reach, t.center - 0.5 * t.axis + reach};
    }
  };
  return std::visit(Visitor{}, shape);
}

}  // namespace penumbra::scenefile
