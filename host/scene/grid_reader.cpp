#include "scene/grid_reader.hpp"

#include <string>

#include "scene/pts_reader.hpp"

namespace penumbra::scenefile {
namespace {

// `spacing: auto` (or no spacing) asks for the EN 12464-1 spacing; a number is metres.
std::optional<double> readSpacing(const Reader& reader, const MapView& map) {
  const std::optional<Field> field = map.find("spacing");
  if (!field || (field->node.IsScalar() && field->node.Scalar() == "auto")) return std::nullopt;
  double probe = 0.0;
  const bool expression = field->node.IsScalar() && expressionText(field->node.Scalar());
  if (!expression && !YAML::convert<double>::decode(field->node, probe)) {
    reader.fail(field->where, "expected a spacing in m or 'auto', got '" +
                                  (field->node.IsScalar() ? field->node.Scalar() : "a list") + "'");
  }
  return reader.positive(*field, "m");
}

WorkPlaneSpec readWorkPlane(const Reader& reader, const MapView& map) {
  WorkPlaneSpec spec;
  spec.heightWhere = spec.marginWhere = map.where();
  if (const std::optional<Field> h = map.find("height")) {
    spec.height = reader.number(*h);
    spec.heightWhere = h->where;
  }
  spec.spacing = readSpacing(reader, map);
  if (const std::optional<Field> m = map.find("margin")) {
    spec.margin = reader.nonNegative(*m, "m");
    spec.marginWhere = m->where;
  }
  return spec;
}

RectGridSpec readRectGrid(const Reader& reader, const MapView& map) {
  const MapView rect =
      reader.map(map.require("rect"), "a grid rectangle {origin: [..], u: [..], v: [..]}");
  rect.allowOnly({"origin", "u", "v"}, "a grid rectangle");
  RectGridSpec spec;
  spec.origin = reader.vec3(rect.require("origin"));
  const Field u = rect.require("u");
  const Field v = rect.require("v");
  spec.u = reader.vec3(u);
  spec.v = reader.vec3(v);
  spec.uWhere = u.where;
  spec.vWhere = v.where;
  spec.spacing = readSpacing(reader, map);
  return spec;
}

PointsSpec readInlinePoints(const Reader& reader, const Field& field) {
  PointsSpec spec;
  for (const Field& row : reader.list(field, "a list of points [x, y, z, nx, ny, nz]")) {
    const std::vector<double> v = reader.numbers(row, 6);
    const Vec3 normal(v[3], v[4], v[5]);
    if (normal == Vec3::Zero())
      reader.fail(row.where, "the normal [nx, ny, nz] is the zero vector");
    spec.positions.emplace_back(v[0], v[1], v[2]);
    spec.normals.push_back(normal.stableNormalized());  // 1e200 would overflow normalized()
  }
  return spec;
}

PointsSpec readPoints(const Reader& reader, const MapView& map) {
  const Field field = map.require("points");
  PointsSpec spec;
  if (field.node.IsScalar()) {
    // A path, relative to the scene file so that a scene and its sensors move together.
    const std::filesystem::path path = reader.file().parent_path() / field.node.Scalar();
    const SensorPoints pts = readPts(path, reader.file(), field.where.line, field.where.key);
    spec.positions = pts.positions;
    spec.normals = pts.normals;
  } else {
    spec = readInlinePoints(reader, field);
  }
  if (spec.positions.empty()) reader.fail(field.where, "the grid has no points");
  return spec;
}

}  // namespace

GridSpec readGrid(const Reader& reader, const Field& field) {
  const MapView map = reader.map(field, "a grid");
  GridSpec grid;
  grid.where = field.where;
  // The kind follows from the keys present: `points`, `rect`, or else a work plane.
  if (map.has("points")) {
    map.allowOnly({"name", "points"}, "a points grid");
    grid.name = reader.text(map.require("name"));
    grid.layout = readPoints(reader, map);
  } else if (map.has("rect")) {
    map.allowOnly({"name", "rect", "spacing"}, "a rect grid");
    grid.name = reader.text(map.require("name"));
    grid.layout = readRectGrid(reader, map);
  } else {
    map.allowOnly({"name", "height", "spacing", "margin"},
                  "a work-plane grid (or give 'rect' or 'points')");
    grid.name = reader.text(map.require("name"));
    grid.layout = readWorkPlane(reader, map);
  }
  return grid;
}

}  // namespace penumbra::scenefile
