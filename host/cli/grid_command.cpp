#include "cli/grid_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>

#include "cl/device.hpp"
#include "cli/progress.hpp"
#include "cli/version.hpp"
#include "lighting/grid_evaluation.hpp"
#include "lighting/illuminance_engine.hpp"
#include "output/result_files.hpp"
#include "output/run_report.hpp"
#include "output/staged_directory.hpp"
#include "output/summary_table.hpp"
#include "reference/reference_illuminance.hpp"
#include "scene/scene_loader.hpp"

namespace penumbra {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A usage problem found after parsing (unknown grid name, bad n): exit status 1.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::vector<const CalculationGrid*> selectGrids(const Scene& scene,
                                                const std::vector<std::string>& wanted) {
  std::vector<const CalculationGrid*> selected;
  for (const std::string& name : wanted) {
    const bool known = std::any_of(scene.grids.begin(), scene.grids.end(),
                                   [&](const CalculationGrid& g) { return g.name == name; });
    if (!known) {
      std::string names;
      for (const CalculationGrid& g : scene.grids) names += (names.empty() ? "" : ", ") + g.name;
      throw UsageError(fmt::format("--grid {}: the scene has no such grid (it has: {})", name,
                                   names.empty() ? "none" : names));
    }
  }
  // Scene order, each grid once, whatever order --grid named them in.
  for (const CalculationGrid& g : scene.grids) {
    if (wanted.empty() || std::find(wanted.begin(), wanted.end(), g.name) != wanted.end()) {
      selected.push_back(&g);
    }
  }
  return selected;
}

// The estimator and what the summary says about it. The kernel path keeps its device and
// engine alive here for the whole run.
struct Estimator {
  IlluminanceEstimator estimate;
  std::size_t batchSize = 1;
  std::string name;    // "kernel" / "reference"
  std::string device;  // in words
  std::optional<compute::Device> clDevice;
  std::unique_ptr<IlluminanceEngine> engine;
};

std::unique_ptr<Estimator> makeEstimator(const Scene& scene, const GridOptions& options) {
  auto estimator = std::make_unique<Estimator>();
  if (options.reference) {
    const int n = options.referenceN;
    estimator->name = "reference";
    estimator->device = fmt::format("host reference (double precision, n = {})", n);
    // About 2^24 samples per source face per batch: a progress step every fraction of a second
    // whatever n is.
    estimator->batchSize = std::clamp<std::size_t>(
        (std::size_t{1} << 24) / (static_cast<std::size_t>(n) * n), 1, 4096);
    estimator->estimate = [&scene, n](std::span<const SamplePoint> points) {
      return referenceIlluminance(scene, points, n);
    };
    return estimator;
  }
  estimator->clDevice.emplace(compute::Device::select(options.device));
  const compute::DeviceInfo& info = estimator->clDevice->info();
  estimator->name = "kernel";
  estimator->device = fmt::format("{} ({}, {})", info.name, info.platform, info.type);
  estimator->engine = std::make_unique<IlluminanceEngine>(*estimator->clDevice, scene);
  estimator->batchSize = 1 << 16;  // large enough to keep a GPU busy, small enough for progress
  estimator->estimate = [engine = estimator->engine.get()](std::span<const SamplePoint> points) {
    return engine->illuminance(points);
  };
  return estimator;
}

int run(const GridOptions& options) {
  const auto start = Clock::now();
  if (options.reference && options.referenceN < 1) {
    throw UsageError(fmt::format("--reference-n {}: must be at least 1", options.referenceN));
  }
  // Fail on an unusable output path before the long part.
  checkOutputTarget(options.output);

  const Scene scene = loadScene(options.scene);
  RunReport report;
  report.version = kVersion;
  report.sceneFile = options.scene;
  report.loadSeconds = secondsSince(start);
  const std::vector<const CalculationGrid*> grids = selectGrids(scene, options.grids);
  if (grids.empty() && !options.quiet) {
    fmt::print(stderr, "penumbra: warning: {} has no calculation grids\n", options.scene.string());
  }

  const auto setupStart = Clock::now();
  const std::unique_ptr<Estimator> estimator = makeEstimator(scene, options);
  report.setupSeconds = secondsSince(setupStart);
  report.estimator = estimator->name;
  report.referenceN = options.reference ? options.referenceN : 0;
  report.device = estimator->device;
  if (!options.quiet) {
    fmt::print(stderr, "penumbra: {} on {}\n", options.scene.string(), report.device);
  }

  ProgressLine progress(!options.quiet);
  for (const CalculationGrid* grid : grids) {
    progress.startGrid(grid->name, grid->positions.size());
    const GridEvaluation evaluation =
        evaluateGrid(scene, *grid, estimator->estimate, estimator->batchSize,
                     [&](std::size_t done, std::size_t total) { progress.update(done, total); });
    progress.finishGrid(evaluation.seconds);
    report.grids.push_back(makeGridReport(scene, *grid, evaluation));
  }
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
  try {
    return run(options);
  } catch (const SceneError& e) {
    // what() is already "file:line: key: message", the form editors turn into a link.
    fmt::print(stderr, "{}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "penumbra: error: {}\n", e.what());
    return 1;
  }
}

}  // namespace penumbra
