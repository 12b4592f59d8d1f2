#include "output/run_report.hpp"

namespace penumbra {

namespace {

GridReport layoutOf(const CalculationGrid& grid) {
  GridReport report;
  report.name = grid.name;
  report.kind = grid.kind;
  report.columns = grid.kind == GridKind::Points ? 0 : grid.columns;
  report.rows = grid.kind == GridKind::Points ? 0 : grid.rows;
  return report;
}

}  // namespace

GridReport makeGridReport(const Scene& scene, const CalculationGrid& grid,
                          const GridEvaluation& evaluation) {
  GridReport report = layoutOf(grid);
  report.name = evaluation.name;
  report.points = evaluation.samples.points;
  report.illuminance = evaluation.illuminance;
  report.seconds = evaluation.seconds;
  report.insideSolids.reserve(evaluation.samples.inside.size());
  for (int solid : evaluation.samples.inside) {
    report.insideSolids.push_back(solid >= 0 ? scene.solids.at(solid).name : std::string());
  }
  report.metrics = evaluation.metrics;
  return report;
}

GridReport streamedGridReport(const CalculationGrid& grid, const GridRun& run) {
  GridReport report = layoutOf(grid);
  report.name = run.name;
  report.metrics = run.metrics;
  report.seconds = run.seconds;
  return report;
}

}  // namespace penumbra
