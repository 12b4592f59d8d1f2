#include "grid/scene_grids.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "illuminance/patch_sky.hpp"

namespace penumbra {

RunReport runReport(const Scene& scene, const std::filesystem::path& sceneFile,
                    const Estimator& estimator, const std::string& version) {
  RunReport report;
  report.version = version;
  report.sceneFile = sceneFile;
  report.parameters = scene.parameters;
  report.estimator = estimator.name();
  report.referenceN = estimator.referenceN();
  report.device = estimator.device();
  if (const InterreflectionReport* solved = estimator.interreflection()) {
    report.interreflection = *solved;
  }
  for (const SceneWarning& warning : scene.warnings) {
    report.warnings.push_back(warningText(scene.file, warning));
  }
  report.luminaires = luminaireReports(scene);
  if (scene.sky) report.sky = skyReport(*scene.sky);
  if (scene.sun)
    report.sun =
        SunReport{scene.sun->position.azimuthDegrees, scene.sun->position.apparentElevationDegrees,
                  scene.sun->directNormalIlluminance, scene.sun->aboveHorizon()};
  return report;
}

SkyReport skyReport(const Sky& sky) {
  SkyReport report;
  report.model = skyModelName(sky.model);
  report.horizontalIlluminance = sky.horizontalIlluminance;
  report.groundReflectance = sky.groundReflectance;
  if (sky.model == SkyModel::CieGeneral) {
    report.cieType = sky.cieType;
    report.subdivision = sky.subdivision;
    report.patches = static_cast<int>(skySubdivision(sky.subdivision).patchCentres.size());
  }
  return report;
}

std::vector<LuminaireReport> luminaireReports(const Scene& scene) {
  std::vector<LuminaireReport> reports;
  for (const Luminaire& l : scene.luminaires) {
    LuminaireReport luminaire{l.name,
                              l.file.string(),
                              photometry::formatName(l.format),
                              static_cast<int>(l.instances.size()),
                              l.lampLumens,
                              l.zonalFluxLm(),
                              l.maintenanceFactor,
                              luminaireModelName(l.model)};
    if (l.opening) {
      luminaire.fitOrder = l.opening->fit.order();
      luminaire.fitError = l.opening->fit.peakRelativeError;
      luminaire.partsAlongLength = l.opening->partsAlongLength;
      luminaire.partsAlongWidth = l.opening->partsAlongWidth;
    }
    reports.push_back(std::move(luminaire));
  }
  return reports;
}

std::vector<const CalculationGrid*> selectGrids(const Scene& scene,
                                                const std::vector<std::string>& wanted) {
  for (const std::string& name : wanted) {
    const bool known = std::any_of(scene.grids.begin(), scene.grids.end(),
                                   [&](const CalculationGrid& g) { return g.name == name; });
    if (!known) {
      std::string names;
      for (const CalculationGrid& g : scene.grids) names += (names.empty() ? "" : ", ") + g.name;
      throw std::invalid_argument(fmt::format("--grid {}: the scene has no such grid (it has: {})",
                                              name, names.empty() ? "none" : names));
    }
  }
  std::vector<const CalculationGrid*> selected;
  for (const CalculationGrid& g : scene.grids) {
    if (wanted.empty() || std::find(wanted.begin(), wanted.end(), g.name) != wanted.end()) {
      selected.push_back(&g);
    }
  }
  return selected;
}

std::vector<GridReport> streamGrids(const Scene& scene,
                                    const std::vector<const CalculationGrid*>& grids,
                                    Estimator& estimator, GridStream& stream,
                                    GridObserver* observer) {
  GridObserver silent;
  GridObserver& watch = observer != nullptr ? *observer : silent;
  const IlluminanceEstimator estimate = estimator.function();
  std::vector<GridReport> reports;
  for (const CalculationGrid* grid : grids) {
    watch.startGrid(grid->name, grid->size());
    stream.start(*grid);
    const GridRun run = streamGrid(
        scene, *grid, estimate, estimator.batchSize(),
        [&](const GridBatch& batch) { stream.write(batch); },
        [&](std::size_t done, std::size_t total) { watch.update(done, total); });
    stream.finish();
    watch.finishGrid(run.seconds);
    reports.push_back(streamedGridReport(*grid, run));
  }
  return reports;
}

namespace {

// Keeps every point of every grid, in the reports' form.
class KeepingStream : public GridStream {
 public:
  explicit KeepingStream(const Scene& scene) : scene_(scene) {}
  void start(const CalculationGrid& grid) override {
    grid_ = &grid;
    kept.emplace_back();
  }
  void write(const GridBatch& batch) override {
    GridReport& report = kept.back();
    for (std::size_t k = 0; k < batch.illuminance.size(); ++k) {
      const std::size_t i = batch.first + k;
      const int inside = batch.inside[k];
      report.points.push_back(SamplePoint{grid_->position(i), grid_->normal(i), batch.onSolid[k]});
      report.insideSolids.push_back(inside >= 0 ? scene_.solids.at(inside).name : std::string());
      report.illuminance.push_back(batch.illuminance[k]);
      // A batch before the estimator's first answer holds inside points only: direct = total = 0.
      report.direct.push_back(batch.direct.empty() ? batch.illuminance[k] : batch.direct[k]);
      if (!batch.sun.empty()) report.sun.push_back(batch.sun[k]);
      if (!batch.sun.empty())
        report.sunReflected.push_back(batch.sunReflected.empty() ? 0.0 : batch.sunReflected[k]);
      // Inside points before the estimator's first answer: components 0; dropped afterwards
      // when the run has none (evaluateGrids).
      report.skyComponent.push_back(batch.skyComponent.empty() ? 0.0 : batch.skyComponent[k]);
      report.externalComponent.push_back(
          batch.externalComponent.empty() ? 0.0 : batch.externalComponent[k]);
    }
  }
  void finish() override {}

  std::vector<GridReport> kept;  // per grid: points, insideSolids and illuminance

 private:
  const Scene& scene_;
  const CalculationGrid* grid_ = nullptr;
};

}  // namespace

std::vector<GridReport> evaluateGrids(const Scene& scene,
                                      const std::vector<const CalculationGrid*>& grids,
                                      Estimator& estimator, GridObserver* observer) {
  KeepingStream keep(scene);
  std::vector<GridReport> reports = streamGrids(scene, grids, estimator, keep, observer);
  for (std::size_t g = 0; g < reports.size(); ++g) {
    reports[g].points = std::move(keep.kept[g].points);
    reports[g].insideSolids = std::move(keep.kept[g].insideSolids);
    reports[g].illuminance = std::move(keep.kept[g].illuminance);
    if (reports[g].directMetrics) reports[g].direct = std::move(keep.kept[g].direct);
    if (reports[g].sunMetrics) {
      reports[g].sun = std::move(keep.kept[g].sun);
      if (reports[g].directMetrics) reports[g].sunReflected = std::move(keep.kept[g].sunReflected);
    }
    if (reports[g].daylight && reports[g].daylight->components) {
      reports[g].skyComponent = std::move(keep.kept[g].skyComponent);
      reports[g].externalComponent = std::move(keep.kept[g].externalComponent);
    }
  }
  return reports;
}

}  // namespace penumbra
