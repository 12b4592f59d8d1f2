#pragma once
// The plots of one finished grid run, written into a folder: what `penumbra plot` writes beside a
// run's results, and what a sweep writes into each case's folder (case_plots.hpp). One function
// for both, so that a case's plots are the very files `penumbra grid --set ... --plot` writes.
// Here the files computed in this process (ParaView files, iso-band SVGs); the PNGs are drawn
// from them by plot_pictures.hpp, where a failure of VTK cannot end the process.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "grid/run_report.hpp"
#include "illuminance/estimator.hpp"
#include "scene/scene.hpp"
#include "viz/plot_options.hpp"
#include "viz/point_light.hpp"

namespace penumbra::viz {

struct PlotFile {
  std::string name;         // in the folder
  std::string description;  // for the list a command prints, e.g. "work-plane.png (800 × 600 px)"
  bool image = false;       // a PNG a person looks at (the others are ParaView files)
};

// The files a plot of `run` writes: per planar grid <stem>.png and <stem>.vti, per point list
// <stem>.vtp, and surfaces.vtp + surfaces.png when the scene has solids. Throws
// std::runtime_error when two would share a name (a grid called "surfaces").
std::vector<std::string> plotFileNames(const RunReport& run, bool withSurfaces);

// The estimator that computes E on the room's surfaces and refines the iso-bands as `run` computed
// its grids: interreflection with the run's element size where the run had it, direct light
// otherwise; on `device`.
EstimatorOptions plotEstimatorOptions(const RunReport& run, const std::string& device);
// What the plots' E includes, for their titles: "total (direct + interreflected)" or "direct
// light only", and the maintenance of `scene`'s luminaires where a factor is below 1
// (maintenanceMeaning).
std::string plotLightName(const RunReport& run, const Scene& scene);
// Told the name of what is drawn next (the command's progress lines); may be empty.
using PlotProgress = std::function<void(const std::string& what)>;

// What the titles say the pictures show: the scene file's name and the parameter values that
// differ from the file's defaults ("office.yaml with window_width_m = 1.6": a `grid --set` run,
// a sweep's case), so that a picture copied out of its folder still tells which case it is.
// Only those: all of a scene's parameters would not fit on the line.
std::string plotSceneName(const std::filesystem::path& sceneFile, const ParameterValues& values);

// Writes the data files of `run`'s plots into the existing `directory`: <grid>.vti / .vtp,
// <grid>.svg with iso-bands, surfaces.vtp. `scene` is the run's scene, loaded with the run's
// parameter values; `light` answers for it (plotEstimatorOptions) and is asked only when the
// scene has solids or iso-bands are drawn. Throws std::runtime_error (clashing names, files) and
// std::invalid_argument (options).
std::vector<PlotFile> writePlotData(const RunReport& run, const Scene& scene,
                                    const PointLight& light, const PlotOptions& options,
                                    const std::filesystem::path& directory,
                                    const PlotProgress& progress = {});

}  // namespace penumbra::viz
