#include "cli/grid_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "cli/exit_status.hpp"
#include "cli/interreflection_notes.hpp"
#include "cli/progress.hpp"
#include "cli/scene_warnings.hpp"
#include "cli/version.hpp"
#include "grid/run_report.hpp"
#include "grid/scene_grids.hpp"
#include "illuminance/estimator.hpp"
#include "output/grid_file_writer.hpp"
#include "output/result_files.hpp"
#include "output/staged_directory.hpp"
#include "output/summary_table.hpp"
#include "scene/scene_loader.hpp"
#include "timing/seconds_since.hpp"

namespace penumbra {

namespace {

// Each grid's .csv and .res, written into the staging directory as its batches come.
class StagedGridFiles : public GridStream {
 public:
  StagedGridFiles(const std::filesystem::path& directory, const Scene& scene, bool withParts,
                  NumberDigits digits)
      : directory_(directory), scene_(scene), withParts_(withParts), digits_(digits) {}
  void start(const CalculationGrid& grid) override {
    files_.emplace(directory_, scene_, grid, withParts_, digits_);
  }
  void write(const GridBatch& batch) override { files_->write(batch); }
  void finish() override {
    files_->close();
    files_.reset();
  }

 private:
  std::filesystem::path directory_;
  const Scene& scene_;
  bool withParts_;
  NumberDigits digits_;
  std::optional<GridFileWriter> files_;
};

int run(const GridOptions& options) {
  const auto start = Clock::now();
  // Fail on an unusable output path before the long part.
  checkOutputTarget(options.output);

  const Scene scene = loadScene(options.scene, options.parameters);
  const double loadSeconds = secondsSince(start);
  const std::vector<const CalculationGrid*> grids = selectGrids(scene, options.grids);
  if (!options.quiet) printSceneWarnings(scene);
  if (grids.empty() && !options.quiet) {
    fmt::print(stderr, "penumbra: warning: {} has no calculation grids\n", options.scene.string());
  }

  const auto setupStart = Clock::now();
  Estimator estimator(options.estimator, scene);
  RunReport report = runReport(scene, options.scene, estimator, kVersion);
  report.loadSeconds = loadSeconds;
  report.setupSeconds = secondsSince(setupStart);
  if (!options.quiet) {
    fmt::print(stderr, "penumbra: {} on {}\n", options.scene.string(), report.device);
    warnAboutBlackSolids(report.interreflection);
    noteLinksPastDenseLimit(report.interreflection, options.estimator.mesh);
  }

  // The files are written while the grids are computed (so that no grid is ever held whole), into
  // a staging directory that appears under the output's name only once everything is written.
  std::vector<std::string> gridNames;
  for (const CalculationGrid* grid : grids) gridNames.push_back(grid->name);
  resultFileNames(gridNames);  // refuses clashing names before anything is created
  StagedDirectory staged(options.output);
  StagedGridFiles files(staged.staging(), scene, report.interreflection.has_value(),
                        illuminanceDigits(report));
  ProgressLine progress(!options.quiet);
  report.grids = streamGrids(scene, grids, estimator, files, &progress);
  report.totalSeconds = secondsSince(start);
  writeSummaryFile(report, staged.staging());
  staged.commit();
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
