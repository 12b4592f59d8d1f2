#pragma once
// A scene's calculation grids → the reports the output layer writes: what `penumbra grid` does for
// one scene and `penumbra sweep` for each case, through the same code.
#include <cstddef>
#include <string>
#include <vector>

#include "evaluation/estimator.hpp"
#include "output/run_report.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// Told about each grid as it is computed (the progress line); every method does nothing by
// default.
class GridObserver {
 public:
  virtual ~GridObserver() = default;
  virtual void startGrid(const std::string& /*name*/, std::size_t /*points*/) {}
  virtual void update(std::size_t /*done*/, std::size_t /*total*/) {}
  virtual void finishGrid(double /*seconds*/) {}
};

// The grids named in `wanted`, in scene order, each once; every grid when `wanted` is empty.
// Throws std::invalid_argument for a name the scene does not have (listing those it has).
std::vector<const CalculationGrid*> selectGrids(const Scene& scene,
                                                const std::vector<std::string>& wanted);

// E and the metrics of each grid, with `estimator` answering for `scene`.
std::vector<GridReport> evaluateGrids(const Scene& scene,
                                      const std::vector<const CalculationGrid*>& grids,
                                      Estimator& estimator, GridObserver* observer = nullptr);

}  // namespace penumbra
