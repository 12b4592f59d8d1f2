#include "grid/run_report.hpp"

namespace penumbra {

GridReport streamedGridReport(const CalculationGrid& grid, const GridRun& run) {
  GridReport report;
  report.name = run.name;
  report.kind = grid.kind;
  report.columns = grid.kind == GridKind::Points ? 0 : grid.columns;
  report.rows = grid.kind == GridKind::Points ? 0 : grid.rows;
  if (report.columns > 0 && report.rows > 0) {
    report.spacingU = grid.u().norm() / report.columns;
    report.spacingV = grid.v().norm() / report.rows;
  }
  report.metrics = run.metrics;
  report.directMetrics = run.directMetrics;
  report.daylight = run.daylight;
  report.sunMetrics = run.sun;
  report.seconds = run.seconds;
  return report;
}

}  // namespace penumbra
