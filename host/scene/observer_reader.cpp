#include "scene/observer_reader.hpp"

#include <cmath>

#include "geometry/tolerance.hpp"

namespace penumbra::scenefile {
namespace {

ObserverGridSpec readObserverGrid(const Reader& reader, const Field& field) {
  const MapView map =
      reader.map(field, "an observer grid {origin: [..], u: [..], v: [..], spacing: ..}");
  map.allowOnly({"origin", "u", "v", "spacing"}, "an observer grid");
  ObserverGridSpec grid;
  grid.origin = reader.vec3(map.require("origin"));
  grid.u = reader.vec3(map.require("u"));
  const Field v = map.require("v");
  grid.v = reader.vec3(v);
  const double scale = std::max(grid.u.norm(), grid.v.norm());
  if (grid.u.cross(grid.v).norm() <= Tolerance::kRelativeInput * scale * scale) {
    reader.fail(v.where, "the grid's sides u " + formatVec3(grid.u) + " and v " +
                             formatVec3(grid.v) + " m span no area");
  }
  grid.spacing = reader.positive(map.require("spacing"), "m");
  return grid;
}

}  // namespace

ObserverSpec readObserver(const Reader& reader, const Field& field) {
  const MapView map = reader.map(field, "an observer");
  map.allowOnly({"name", "eye", "grid", "look"}, "an observer");
  ObserverSpec spec;
  spec.where = field.where;
  spec.name = reader.text(map.require("name"));
  const std::optional<Field> eye = map.find("eye");
  const std::optional<Field> grid = map.find("grid");
  if (eye && grid) reader.fail(grid->where, "give either 'eye' or 'grid', not both");
  if (!eye && !grid) {
    reader.fail(map.where(),
                "an observer needs 'eye: [x, y, z]' (m) or 'grid: {origin, u, v, "
                "spacing}'");
  }
  if (eye) {
    spec.eyes = reader.vec3(*eye);
    spec.eyeWhere = eye->where;
  } else {
    spec.eyes = readObserverGrid(reader, *grid);
    spec.eyeWhere = grid->where;
  }
  if (const std::optional<Field> look = map.find("look")) {
    const Vec3 direction = reader.direction(*look);
    // The Guth position index measures a source above the line of sight in the vertical plane
    // through it: a line of sight straight up or down has no such plane.
    if (std::hypot(direction.x(), direction.y()) < Tolerance::kInputAngle) {
      reader.fail(look->where, "'look' " + formatVec3(direction) +
                                   " points straight up or down; UGR rates a line of sight with "
                                   "a horizontal component (e.g. [1, 0, 0])");
    }
    spec.look = direction;
  }
  return spec;
}

}  // namespace penumbra::scenefile
