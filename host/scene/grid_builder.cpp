#include "scene/grid_builder.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include <fmt/format.h>

namespace penumbra::scenefile {
namespace {

// Points at the centres of the cells of the parallelogram origin + [0,1]·u + [0,1]·v, cut into
// cells no longer than `maxSpacing` along u and v. Row-major, rows along v.
CalculationGrid planarGrid(const std::string& name, GridKind kind, const Vec3& origin,
                           const Vec3& u, const Vec3& v, double maxSpacing, const Where& where,
                           const BuildContext& context) {
  // A spacing typed in mm instead of m would ask for billions of points; stop before allocating.
  constexpr double kMaxPoints = 1e7;
  const double points = std::ceil(u.norm() / maxSpacing) * std::ceil(v.norm() / maxSpacing);
  if (points > kMaxPoints) {
    context.fail(where, "a spacing of " + formatNumber(maxSpacing) + " m gives about " +
                            fmt::format("{:.0f}", points) +
                            " points, more than the limit of 10 million");
  }
  const int columns = cellCount(u.norm(), maxSpacing);
  const int rows = cellCount(v.norm(), maxSpacing);
  const double spacing = std::max(u.norm() / columns, v.norm() / rows);
  return CalculationGrid::planar(name, kind, origin, u, v, columns, rows, spacing);
}

CalculationGrid workPlane(const GridSpec& spec, const WorkPlaneSpec& plane,
                          const std::optional<Room>& room, const BuildContext& context) {
  if (!room) {
    context.fail(spec.where,
                 "a work-plane grid covers the room's floor, but the scene has no "
                 "'room:'; give this grid a 'rect:' or 'points:' instead");
  }
  const Vec3& size = room->size;
  if (plane.height < 0.0 || plane.height > size.z()) {
    context.fail(plane.heightWhere, "the work plane's height " + formatNumber(plane.height) +
                                        " m is outside the room (0 to " + formatNumber(size.z()) +
                                        " m)");
  }
  // EN 12464-1: the calculation area is the floor less a band of `margin` along the walls.
  const double sideX = size.x() - 2.0 * plane.margin;
  const double sideY = size.y() - 2.0 * plane.margin;
  if (sideX <= context.tolerance || sideY <= context.tolerance) {
    context.fail(plane.marginWhere,
                 "the grid has no points: a margin of " + formatNumber(plane.margin) +
                     " m along the walls leaves no calculation area in the " +
                     formatNumber(size.x()) + " × " + formatNumber(size.y()) + " m room");
  }
  const double p = plane.spacing ? *plane.spacing : en12464Spacing(std::max(sideX, sideY));
  return planarGrid(spec.name, GridKind::WorkPlane, Vec3(plane.margin, plane.margin, plane.height),
                    Vec3(sideX, 0.0, 0.0), Vec3(0.0, sideY, 0.0), p, spec.where, context);
}

CalculationGrid rectGrid(const GridSpec& spec, const RectGridSpec& rect,
                         const BuildContext& context) {
  if (rect.u.norm() <= context.tolerance) {
    context.fail(rect.uWhere, "the grid has no points: its side u has zero length");
  }
  if (rect.v.norm() <= context.tolerance) {
    context.fail(rect.vWhere, "the grid has no points: its side v has zero length");
  }
  if (std::abs(rect.u.normalized().dot(rect.v.normalized())) > kInputAngleTolerance) {
    context.fail(rect.vWhere, "the grid rectangle's sides u " + formatVec3(rect.u) + " and v " +
                                  formatVec3(rect.v) + " are not perpendicular");
  }
  const double p =
      rect.spacing ? *rect.spacing : en12464Spacing(std::max(rect.u.norm(), rect.v.norm()));
  return planarGrid(spec.name, GridKind::Rect, rect.origin, rect.u, rect.v, p, spec.where, context);
}

CalculationGrid pointGrid(const GridSpec& spec, const PointsSpec& points) {
  return CalculationGrid::pointList(spec.name, points.positions, points.normals);
}

}  // namespace

double en12464Spacing(double d) {
  // EN 12464-1 caps the cell size at 10 m, reached for d ≈ 270 m.
  constexpr double kMaxSpacing = 10.0;
  return std::min(0.2 * std::pow(5.0, std::log10(d)), kMaxSpacing);
}

int cellCount(double side, double p) {
  // The small slack keeps a spacing that divides the side exactly (1.4 m at 0.1 m) from gaining
  // a cell to the rounding of side / p.
  return std::max(1, static_cast<int>(std::ceil(side / p - 1e-9)));
}

CalculationGrid buildGrid(const GridSpec& spec, const std::optional<Room>& room,
                          const BuildContext& context) {
  if (const auto* plane = std::get_if<WorkPlaneSpec>(&spec.layout)) {
    return workPlane(spec, *plane, room, context);
  }
  if (const auto* rect = std::get_if<RectGridSpec>(&spec.layout)) {
    return rectGrid(spec, *rect, context);
  }
  return pointGrid(spec, std::get<PointsSpec>(spec.layout));
}

}  // namespace penumbra::scenefile
