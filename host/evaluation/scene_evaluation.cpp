#include "evaluation/scene_evaluation.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace penumbra {

std::vector<const CalculationGrid*> selectGrids(const Scene& scene,
                                                const std::vector<std::string>& wanted) {
  for (const std::string& name : wanted) {
    const bool known = std::any_of(scene.grids.begin(), scene.grids.end(),
                                   [&](const CalculationGrid& g) { return g.name == name; });
    if (!known) {
      std::string names;
      for (const CalculationGrid& g : scene.grids) names += (names.empty() ? "" : ", ") + g.name;
      throw std::invalid_argument(fmt::format("--grid {}: the scene has no such grid (it has: {})",
                                              name, names.empty() ? "none" : names));
    }
  }
  std::vector<const CalculationGrid*> selected;
  for (const CalculationGrid& g : scene.grids) {
    if (wanted.empty() || std::find(wanted.begin(), wanted.end(), g.name) != wanted.end()) {
      selected.push_back(&g);
    }
  }
  return selected;
}

std::vector<GridReport> evaluateGrids(const Scene& scene,
                                      const std::vector<const CalculationGrid*>& grids,
                                      Estimator& estimator, GridObserver* observer) {
  GridObserver silent;
  GridObserver& watch = observer != nullptr ? *observer : silent;
  const IlluminanceEstimator estimate = estimator.function();
  std::vector<GridReport> reports;
  for (const CalculationGrid* grid : grids) {
    watch.startGrid(grid->name, grid->size());
    const GridEvaluation evaluation =
        evaluateGrid(scene, *grid, estimate, estimator.batchSize(),
                     [&](std::size_t done, std::size_t total) { watch.update(done, total); });
    watch.finishGrid(evaluation.seconds);
    reports.push_back(makeGridReport(scene, *grid, evaluation));
  }
  return reports;
}

std::vector<GridReport> streamGrids(const Scene& scene,
                                    const std::vector<const CalculationGrid*>& grids,
                                    Estimator& estimator, GridStream& stream,
                                    GridObserver* observer) {
  GridObserver silent;
  GridObserver& watch = observer != nullptr ? *observer : silent;
  const IlluminanceEstimator estimate = estimator.function();
  std::vector<GridReport> reports;
  for (const CalculationGrid* grid : grids) {
    watch.startGrid(grid->name, grid->size());
    stream.start(*grid);
    const GridRun run = streamGrid(
        scene, *grid, estimate, estimator.batchSize(),
        [&](const GridBatch& batch) { stream.write(batch); },
        [&](std::size_t done, std::size_t total) { watch.update(done, total); });
    stream.finish();
    watch.finishGrid(run.seconds);
    reports.push_back(streamedGridReport(*grid, run));
  }
  return reports;
}

}  // namespace penumbra
