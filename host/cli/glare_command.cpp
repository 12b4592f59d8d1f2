#include "cli/glare_command.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <optional>

#include "cli/exit_status.hpp"
#include "cli/scene_warnings.hpp"
#include "cli/version.hpp"
#include "glare/observer_ratings.hpp"
#include "output/glare_files.hpp"
#include "output/staged_directory.hpp"
#include "scene/scene_loader.hpp"
#include "timing/seconds_since.hpp"

namespace penumbra {
namespace {

int run(const GlareOptions& options) {
  const auto start = Clock::now();
  checkOutputTarget(options.output);
  const Scene scene = loadScene(options.scene, options.parameters);
  if (!options.quiet) printSceneWarnings(scene);
  if (scene.observers.empty()) {
    throw std::runtime_error(fmt::format(
        "{} has no observers: add an 'observers:' list (docs/scene-format.md, \"Observers\")",
        options.scene.string()));
  }

  GlareRun run;
  run.sceneFile = options.scene;
  run.version = kVersion;
  run.interreflection = options.estimator.interreflection;
  // Direct light only: L_b = 0 and every UGR is undefined; no device is needed for that.
  std::optional<Estimator> estimator;
  IndirectIlluminance indirect = [](std::span<const SamplePoint> points) {
    return std::vector<double>(points.size(), 0.0);
  };
  if (run.interreflection) {
    EstimatorOptions estimatorOptions = options.estimator;
    estimatorOptions.reference = false;
    estimator.emplace(estimatorOptions, scene);
    run.device = estimator->device();
    indirect = [&](std::span<const SamplePoint> points) {
      return estimator->interreflected(points);
    };
  } else {
    run.device = "none (direct light only)";
  }
  if (!options.quiet)
    fmt::print(stderr, "penumbra: {} on {}\n", options.scene.string(), run.device);
  run.ratings = rateObservers(scene, indirect);
  run.seconds = secondsSince(start);

  StagedDirectory staged(options.output);
  writeGlareFiles(run, staged.staging());
  staged.commit();
  if (!options.quiet) {
    fmt::print("{}", glareTable(run));
    fmt::print("results in {}\n", normalizedTarget(options.output).string());
  }
  return 0;
}

}  // namespace

int runGlareCommand(const GlareOptions& options) {
  return cli::reportingErrors([&] { return run(options); });
}

}  // namespace penumbra
