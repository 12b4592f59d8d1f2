#include "viz/plot_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "cl/device.hpp"
#include "cli/exit_status.hpp"
#include "illuminance/estimator.hpp"
#include "output/result_reader.hpp"
#include "output/staged_directory.hpp"
#include "scene/scene_loader.hpp"
#include "viz/colour_scale.hpp"
#include "viz/plot_files.hpp"
#include "viz/plot_pictures.hpp"
#include "viz/render_png.hpp"
#include "viz/ugr_map.hpp"

namespace penumbra::viz {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

void checkOptions(const PlotOptions& options) {
  if (options.width < 400 || options.width > 8000) {
    throw std::invalid_argument(fmt::format("--width {}: must be 400 to 8000 px", options.width));
  }
  colourScale(options.legend, 0.0, 1.0);  // a bad --range fails here, before any work
  for (double level : options.isolux) {
    if (!(level > 0.0)) throw std::invalid_argument("--isolux: every level must be above 0 lx");
  }
}

// The folder of `penumbra glare`: one UGR map per observer grid.
int runUgrMaps(const PlotOptions& options, const nlohmann::json& summary) {
  const auto start = Clock::now();
  const fs::path sceneFile = summary.at("scene").get<std::string>();
  if (!fs::exists(sceneFile)) {
    throw std::runtime_error(
        fmt::format("the scene of this run, {}, is not there any more", sceneFile.string()));
  }
  const Scene scene = loadScene(sceneFile);
  const std::vector<UgrGrid> grids = ugrGrids(summary);
  if (grids.empty()) {
    throw std::runtime_error(fmt::format(
        "{} has no observer grid of at least 2 x 2 eyes to map (single eyes are in the CSVs)",
        options.folder.string()));
  }
  StagedDirectory staged(options.folder);
  std::vector<std::string> written;
  for (const UgrGrid& grid : grids) {
    const std::string name = ugrMapFileName(grid.entry);
    const std::string subtitle = fmt::format(
        "{} · eyes at {:.2f} m · {} × {} eyes, {:.3g} m × {:.3g} m apart · {}",
        sceneFile.filename().string(), grid.field.first.z(), grid.field.columns, grid.field.rows,
        grid.field.uStep.norm(), grid.field.vStep.norm(), summary.value("background", ""));
    const HeatMapFigure figure =
        drawUgrMap(grid, scene, options.ugrLimit, options.width, subtitle, staged.staging() / name);
    written.push_back(
        fmt::format("{} ({} × {} px)", name, figure.layout.width, figure.layout.height));
  }
  staged.commit();
  if (!options.quiet) {
    for (const std::string& file : written) fmt::print("{}\n", file);
    fmt::print("plots in {} ({:.1f} s)\n", normalizedTarget(options.folder).string(),
               std::chrono::duration<double>(Clock::now() - start).count());
  }
  return 0;
}

int run(const PlotOptions& options) {
  const auto start = Clock::now();
  checkOptions(options);
  requireDisplay();
  if (const nlohmann::json summary = readSummary(options.folder / "summary.json");
      summary.contains("observers")) {
    return runUgrMaps(options, summary);
  }
  const RunReport results = readResults(options.folder);
  if (!fs::exists(results.sceneFile)) {
    throw std::runtime_error(fmt::format("the scene of this run, {}, is not there any more",
                                         results.sceneFile.string()));
  }
  if (!options.quiet && fs::last_write_time(results.sceneFile) >
                            fs::last_write_time(options.folder / "summary.json")) {
    fmt::print(stderr,
               "penumbra: warning: {} changed after this run; outlines and surfaces show it as "
               "it is now\n",
               results.sceneFile.string());
  }
  // The scene as the run computed it: with its parameter values (`grid --set`), not the defaults.
  const Scene scene = loadScene(results.sceneFile, results.parameters);

  // The device is opened (and the interreflection solved) only when the surfaces or the
  // iso-bands need it, and only once.
  std::unique_ptr<Estimator> estimator;
  const PointLight light = [&](std::span<const SamplePoint> points) {
    if (!estimator)
      estimator = std::make_unique<Estimator>(plotEstimatorOptions(results, options.device), scene);
    return estimator->illuminance(points).total;
  };
  const PlotProgress progress = [&](const std::string& what) {
    if (!options.quiet) fmt::print(stderr, "penumbra: {}\n", what);
  };
  // The data files first, all together (the results are there already); then the pictures,
  // drawn from them where VTK's failure cannot end this process.
  StagedDirectory staged(options.folder);
  const std::vector<PlotFile> written =
      writePlotData(results, scene, light, options, staged.staging(), progress);
  staged.commit();
  const PicturesWritten pictures =
      drawPlotPictures(results, scene, options, options.folder, progress);
  if (!options.quiet) {
    for (const PlotFile& file : written) fmt::print("{}\n", file.description);
    fmt::print("{} picture{} drawn, {} kept (the same data)\n", pictures.drawn,
               pictures.drawn == 1 ? "" : "s", pictures.kept);
    fmt::print("plots in {} ({:.1f} s)\n", normalizedTarget(options.folder).string(),
               std::chrono::duration<double>(Clock::now() - start).count());
  }
  if (!pictures.missing.empty()) {
    fmt::print(stderr,
               "penumbra: error: {}: {}\n  the results and the ParaView files are written; "
               "`penumbra plot {}` draws only the missing pictures\n",
               normalizedTarget(options.folder).string(), missingPictures(pictures, "picture"),
               options.folder.string());
    return 1;
  }
  return 0;
}

}  // namespace

int runPlotCommand(const PlotOptions& options) {
  return cli::reportingErrors([&] { return run(options); });
}

}  // namespace penumbra::viz
