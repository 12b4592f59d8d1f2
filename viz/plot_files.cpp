#include "viz/plot_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "grid/scene_grids.hpp"
#include "output/result_files.hpp"
#include "scene/scene_loader.hpp"
#include "viz/grid_dataset.hpp"
#include "viz/isoband_svg.hpp"
#include "viz/surfaces_plot.hpp"

namespace penumbra::viz {

namespace {

namespace fs = std::filesystem;

void writeGridData(const GridReport& grid, const fs::path& directory,
                   std::vector<PlotFile>& written) {
  const std::string dataset = gridDatasetFileName(grid);
  writeGridDataset(grid, directory / dataset);
  written.push_back({dataset, dataset, false});
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

std::string plotSceneName(const fs::path& sceneFile, const ParameterValues& values) {
  const std::string name = sceneFile.filename().string();
  if (values.empty()) return name;
  const ParameterValues defaults = loadSceneParameters(sceneFile);
  ParameterValues changed;
  for (const ParameterValue& p : values) {
    const auto same = std::find(defaults.begin(), defaults.end(), p);
    if (same == defaults.end()) changed.push_back(p);
  }
  return changed.empty() ? name : name + " with " + describeParameters(changed);
}

EstimatorOptions plotEstimatorOptions(const RunReport& run, const std::string& device) {
  EstimatorOptions estimator;
  estimator.device = device;
  estimator.interreflection = run.interreflection.has_value();
  if (run.interreflection) estimator.mesh.elementSize = run.interreflection->elementSize;
  return estimator;
}

std::string plotLightName(const RunReport& run, const Scene& scene) {
  const std::string maintenance = maintenanceMeaning(luminaireReports(scene));
  return std::string(run.interreflection ? "total (direct + interreflected)"
                                         : "direct light only") +
         (maintenance.empty() ? "" : ", " + maintenance);
}

std::vector<PlotFile> writePlotData(const RunReport& run, const Scene& scene,
                                    const PointLight& light, const PlotOptions& options,
                                    const fs::path& directory, const PlotProgress& progress) {
  const bool withSurfaces = !scene.solids.empty();
  plotFileNames(run, withSurfaces);  // refuses clashing names before anything is drawn
  std::vector<PlotFile> written;
  for (const GridReport& grid : run.grids) {
    writeGridData(grid, directory, written);
    if (options.isobands > 0 && grid.kind != GridKind::Points) {
      const auto planar =
          std::find_if(scene.grids.begin(), scene.grids.end(),
                       [&](const CalculationGrid& g) { return g.name == grid.name; });
      if (planar == scene.grids.end()) continue;
      const std::string svg = gridFileStem(grid.name) + ".svg";
      const IsobandFigure figure =
          writeGridIsobands(*planar, grid.illuminance, light, options.isobands, directory / svg);
      written.push_back({svg,
                         fmt::format("{} ({} bands, {} polygons)", svg, figure.levels.size() + 1,
                                     figure.polygons),
                         true});
    }
  }
  if (withSurfaces) {
    if (progress) progress("illuminance on the room's surfaces");
    const SurfacesPlot surfaces = writeSurfacesFile(scene, light, options, directory);
    written.push_back(
        {"surfaces.vtp",
         fmt::format("surfaces.vtp ({} points, {} m apart)", surfaces.points, surfaces.spacing),
         false});
  }
  return written;
}

}  // namespace penumbra::viz
