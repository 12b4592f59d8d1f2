#include "output/run_report.hpp"

namespace penumbra {

GridReport makeGridReport(const Scene& scene, const CalculationGrid& grid,
                          const GridEvaluation& evaluation) {
  GridReport report;
  report.name = evaluation.name;
  report.kind = grid.kind;
  report.columns = grid.kind == GridKind::Points ? 0 : grid.columns;
  report.rows = grid.kind == GridKind::Points ? 0 : grid.rows;
  report.points = evaluation.samples.points;
  report.illuminance = evaluation.illuminance;
  report.seconds = evaluation.seconds;
  report.insideSolids.reserve(evaluation.samples.inside.size());
  for (int solid : evaluation.samples.inside) {
    report.insideSolids.push_back(solid >= 0 ? scene.solids.at(solid).name : std::string());
  }
  report.metrics = gridMetrics(evaluation.illuminance, evaluation.samples.inside, grid.spacing);
  return report;
}

}  // namespace penumbra
