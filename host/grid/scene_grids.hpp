#pragma once
// A scene's calculation grids → the reports the output layer writes: what `penumbra grid` does for
// one scene and `penumbra sweep` for each case, through the same code.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "grid/run_report.hpp"
#include "illuminance/estimator.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// A run's report before its grids are computed: penumbra's version, the scene file and its
// parameters, and what computes E (kernel or reference, the device). `penumbra grid` and each case
// of `penumbra sweep` start from it and add their grids and times.
RunReport runReport(const Scene& scene, const std::filesystem::path& sceneFile,
                    const Estimator& estimator, const std::string& version);
// The sky as summary.json records it: model, E_h, ρ_g, and a cie-general sky's type,
// subdivision and patch count.
SkyReport skyReport(const Sky& sky);
// The scene's photometric luminaires as the reports list them (flux, maintenance factor).
std::vector<LuminaireReport> luminaireReports(const Scene& scene);

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

// E and the metrics of each grid, with `estimator` answering for `scene`; every point is kept in
// the reports (a sweep's case plots draw them).
std::vector<GridReport> evaluateGrids(const Scene& scene,
                                      const std::vector<const CalculationGrid*>& grids,
                                      Estimator& estimator, GridObserver* observer = nullptr);

// Where the points of each grid go while they are computed: start() before a grid's first batch,
// its batches in grid order, finish() after its last.
class GridStream {
 public:
  virtual ~GridStream() = default;
  virtual void start(const CalculationGrid& grid) = 0;
  virtual void write(const GridBatch& batch) = 0;
  virtual void finish() = 0;
};

// The same, each grid's points handed to `stream` batch by batch and not kept: memory does not
// grow with the number of points. The reports hold layouts, metrics and times only.
std::vector<GridReport> streamGrids(const Scene& scene,
                                    const std::vector<const CalculationGrid*>& grids,
                                    Estimator& estimator, GridStream& stream,
                                    GridObserver* observer = nullptr);

}  // namespace penumbra
