#include "cli/grid_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>

#include "cli/exit_status.hpp"
#include "cli/progress.hpp"
#include "cli/version.hpp"
#include "evaluation/estimator.hpp"
#include "evaluation/scene_evaluation.hpp"
#include "output/result_files.hpp"
#include "output/run_report.hpp"
#include "output/staged_directory.hpp"
#include "output/summary_table.hpp"
#include "scene/scene_loader.hpp"

namespace penumbra {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

EstimatorOptions estimatorOptions(const GridOptions& options) {
  return EstimatorOptions{options.device, options.reference, options.referenceN, options.culling};
}

int run(const GridOptions& options) {
  const auto start = Clock::now();
  // Fail on an unusable output path before the long part.
  checkOutputTarget(options.output);

  const Scene scene = loadScene(options.scene, options.parameters);
  RunReport report;
  report.version = kVersion;
  report.sceneFile = options.scene;
  report.parameters = scene.parameters;
  report.loadSeconds = secondsSince(start);
  const std::vector<const CalculationGrid*> grids = selectGrids(scene, options.grids);
  if (grids.empty() && !options.quiet) {
    fmt::print(stderr, "penumbra: warning: {} has no calculation grids\n", options.scene.string());
  }

  const auto setupStart = Clock::now();
  Estimator estimator(estimatorOptions(options), scene);
  report.setupSeconds = secondsSince(setupStart);
  report.estimator = estimator.name();
  report.referenceN = estimator.referenceN();
  report.device = estimator.device();
  if (!options.quiet) {
    fmt::print(stderr, "penumbra: {} on {}\n", options.scene.string(), report.device);
  }

  ProgressLine progress(!options.quiet);
  report.grids = evaluateGrids(scene, grids, estimator, &progress);
  report.totalSeconds = secondsSince(start);

  writeResults(report, options.output);
  if (!options.quiet) {
    fmt::print("{}", summaryTable(report));
    fmt::print("results in {}\n", normalizedTarget(options.output).string());
  }
  return 0;
}

}  // namespace

int runGridCommand(const GridOptions& options) {
  return cli::reportingErrors([&] { return run(options); });
}

}  // namespace penumbra
