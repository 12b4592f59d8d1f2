#include "viz/plot_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "cli/exit_status.hpp"
#include "output/result_files.hpp"
#include "output/result_reader.hpp"
#include "output/staged_directory.hpp"
#include "scene/scene_loader.hpp"
#include "viz/colour_scale.hpp"
#include "viz/grid_dataset.hpp"
#include "viz/heat_map.hpp"
#include "viz/isolux_lines.hpp"
#include "viz/planar_field.hpp"
#include "viz/render_png.hpp"
#include "viz/surfaces_plot.hpp"

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

// The line under a heat map's metrics: where the numbers come from.
std::string heatMapSubtitle(const GridReport& grid, const PlanarField& field,
                            const std::string& sceneName) {
  std::string where;
  if (grid.kind == GridKind::WorkPlane) {
    where = fmt::format("work plane at {:.2f} m", field.first.z());
  } else {
    where = fmt::format("rectangle facing ({:.3g}, {:.3g}, {:.3g})", field.normal.x(),
                        field.normal.y(), field.normal.z());
  }
  std::string text =
      fmt::format("{} · {} · {} × {} points, {:.3g} m × {:.3g} m apart", sceneName, where,
                  field.columns, field.rows, field.uStep.norm(), field.vStep.norm());
  if (grid.metrics.pointsInsideSolids > 0) {
    text += fmt::format(" · {} inside solids, left out", grid.metrics.pointsInsideSolids);
  }
  return text;
}

std::vector<double> isoluxFor(const PlotOptions& options, const GridMetrics& metrics) {
  if (options.noIsolux) return {};
  if (!options.isolux.empty()) return options.isolux;
  return autoIsoluxLevels(metrics.eMin, metrics.eMax);
}

void plotGrid(const GridReport& grid, const Scene& scene, const PlotOptions& options,
              const std::string& sceneName, const fs::path& directory,
              std::vector<std::string>& written) {
  const std::string dataset = gridDatasetFileName(grid);
  writeGridDataset(grid, directory / dataset);
  written.push_back(dataset);
  if (grid.kind == GridKind::Points) return;

  const PlanarField field = planarField(grid);
  HeatMapStyle style;
  style.scale = colourScale(options.legend, grid.metrics.eMin, grid.metrics.eMax);
  style.isolux = isoluxFor(options, grid.metrics);
  style.width = options.width;
  style.subtitle = heatMapSubtitle(grid, field, sceneName);
  const std::string png = gridFileStem(grid.name) + ".png";
  const HeatMapFigure figure = drawHeatMap(field, grid.metrics, scene, style, directory / png);
  written.push_back(fmt::format("{} ({} × {} px)", png, figure.layout.width, figure.layout.height));
}

int run(const PlotOptions& options) {
  const auto start = Clock::now();
  checkOptions(options);
  requireDisplay();
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
  const Scene scene = loadScene(results.sceneFile);
  const bool withSurfaces = !scene.solids.empty();
  plotFileNames(results, withSurfaces);  // refuses clashing names before anything is created
  const std::string sceneName = results.sceneFile.filename().string();

  StagedDirectory staged(options.folder);
  std::vector<std::string> written;
  for (const GridReport& grid : results.grids) {
    if (!options.quiet) fmt::print(stderr, "penumbra: plotting {}\n", grid.name);
    plotGrid(grid, scene, options, sceneName, staged.staging(), written);
  }
  if (withSurfaces) {
    if (!options.quiet) fmt::print(stderr, "penumbra: illuminance on the room's surfaces\n");
    const SurfacesPlot surfaces = plotSurfaces(scene, options, sceneName, staged.staging());
    written.push_back(
        fmt::format("surfaces.vtp ({} points, {} m apart)", surfaces.points, surfaces.spacing));
    written.push_back(fmt::format("surfaces.png ({} × {} px)", surfaces.width, surfaces.height));
  }
  staged.commit();
  if (!options.quiet) {
    for (const std::string& line : written) fmt::print("{}\n", line);
    fmt::print("plots in {} ({:.1f} s)\n", normalizedTarget(options.folder).string(),
               std::chrono::duration<double>(Clock::now() - start).count());
  }
  return 0;
}

}  // namespace

std::vector<std::string> plotFileNames(const RunReport& run, bool withSurfaces) {
  std::vector<std::string> names;
  for (const GridReport& grid : run.grids) {
    names.push_back(gridDatasetFileName(grid));
    if (grid.kind != GridKind::Points) names.push_back(gridFileStem(grid.name) + ".png");
  }
  if (withSurfaces) {
    names.push_back("surfaces.vtp");
    names.push_back("surfaces.png");
  }
  std::set<std::string> seen;
  for (const std::string& name : names) {
    if (!seen.insert(name).second) {
      throw std::runtime_error(fmt::format(
          "two plots would be written to {}: rename the grid (\"surfaces\" is taken by the "
          "room's surfaces)",
          name));
    }
  }
  return names;
}

int runPlotCommand(const PlotOptions& options) {
  return cli::reportingErrors([&] { return run(options); });
}

}  // namespace penumbra::viz
