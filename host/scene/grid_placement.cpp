#include "scene/grid_placement.hpp"

#include <algorithm>
#include <string>

#include <fmt/format.h>

#include "scene/placement.hpp"

namespace penumbra::scenefile {
namespace {

// The grid's rectangle meets the closed interior box (grown by the tolerance): clipped by the
// box's six planes, something is left.
bool meetsBox(const ConvexPolygon& rectangle, const BoundingBox& box, double tolerance) {
  ConvexPolygon part = rectangle;
  for (int axis = 0; axis < 3 && !part.empty(); ++axis) {
    const Vec3 n = Vec3::Unit(axis);
    part = part.clipped(Plane{n, box.hi[axis]}, tolerance);
    part = part.clipped(Plane{-n, -box.lo[axis]}, tolerance);
  }
  return !part.empty();
}

bool facesSomeSource(const Plane& plane, const std::vector<Source>& sources, double tolerance) {
  return std::any_of(sources.begin(), sources.end(), [&](const Source& source) {
    return std::any_of(source.faces.begin(), source.faces.end(), [&](const ConvexPolygon& face) {
      return anyInFront(plane, face.vertices(), tolerance);
    });
  });
}

}  // namespace

std::optional<SceneWarning> misplacedGridWarning(const CalculationGrid& grid, const Where& where,
                                                 const Scene& scene, double tolerance) {
  if (grid.kind != GridKind::Rect) return std::nullopt;
  const Vec3& o = grid.origin();
  const ConvexPolygon rectangle({o, o + grid.u(), o + grid.u() + grid.v(), o + grid.v()});
  if (solidHolding(scene.solids, rectangle.vertices(), tolerance) >= 0) return std::nullopt;
  const auto warning = [&](const std::string& what) {
    return SceneWarning{where.line, where.key, fmt::format("grid '{}' {}", grid.name, what)};
  };
  const BoundingBox room = roomInterior(scene.room);
  if (!room.empty() && !meetsBox(rectangle, room, tolerance)) {
    return warning(
        fmt::format("lies outside the room (it spans {}; the room's interior spans "
                    "{}); check its origin",
                    describeExtent(rectangle.vertices()), describeExtent({room.lo, room.hi})));
  }
  const Vec3 normal = grid.normal(0);
  if (!scene.sources.empty() &&
      !facesSomeSource(Plane::through(o, normal), scene.sources, tolerance)) {
    return warning(
        fmt::format("faces away from every source: its normal u × v is {}; swap u "
                    "and v to turn it over",
                    describeDirection(normal)));
  }
  return std::nullopt;
}

}  // namespace penumbra::scenefile
