#include "scene/observer_builder.hpp"

#include <fmt/format.h>

#include <variant>

#include "scene/eye_placement.hpp"
#include "scene/grid_builder.hpp"

namespace penumbra::scenefile {

std::vector<Vec3> defaultLooks() {
  return {Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitX(), -Vec3::UnitY()};
}

std::vector<Observer> buildObservers(const ObserverSpec& spec, const std::vector<Solid>& solids,
                                     const BuildContext& context) {
  const std::vector<Vec3> looks = spec.look ? std::vector<Vec3>{*spec.look} : defaultLooks();
  std::vector<Observer> observers;
  if (const auto* eye = std::get_if<Vec3>(&spec.eyes)) {
    observers.push_back(Observer{spec.name, spec.name, *eye, looks});
  } else {
    const auto& grid = std::get<ObserverGridSpec>(spec.eyes);
    // An observer is rated on the host, source by source: a few thousand eyes is already a long
    // run, and more is a spacing typed in the wrong unit.
    constexpr int kMaxEyes = 10000;
    const int columns = cellCount(grid.u.norm(), grid.spacing);
    const int rows = cellCount(grid.v.norm(), grid.spacing);
    if (static_cast<double>(columns) * rows > kMaxEyes) {
      context.fail(spec.eyeWhere,
                   fmt::format("a spacing of {} m gives {} × {} eyes, more than the limit of {}",
                               formatNumber(grid.spacing), columns, rows, kMaxEyes));
    }
    const CalculationGrid cells = CalculationGrid::planar(
        spec.name, GridKind::Rect, grid.origin, grid.u, grid.v, columns, rows, grid.spacing);
    for (int row = 0; row < rows; ++row) {
      for (int column = 0; column < columns; ++column) {
        const Vec3 eye = cells.position(static_cast<std::size_t>(row) * columns + column);
        observers.push_back(Observer{fmt::format("{}[{},{}]", spec.name, column + 1, row + 1),
                                     spec.name, eye, looks});
      }
    }
  }
  for (const Observer& observer : observers) {
    requireEyeOutsideSolids(observer.eye, fmt::format("observer '{}'", observer.name),
                            spec.eyeWhere, solids, context);
  }
  return observers;
}

}  // namespace penumbra::scenefile
