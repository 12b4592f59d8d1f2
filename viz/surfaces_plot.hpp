#pragma once
// The room's surfaces in false colour: sample every face, compute E there with the OpenCL
// engine, write surfaces.vtp and render surfaces.png.
#include <filesystem>
#include <string>

#include "engine/illuminance_engine.hpp"
#include "scene/scene.hpp"
#include "viz/plot_options.hpp"

namespace penumbra::viz {

struct SurfacesPlot {
  double spacing = 0.0;  // m, as used
  std::size_t points = 0;
  int width = 0, height = 0;  // of the PNG, px
};

// Writes surfaces.vtp and surfaces.png into `directory`. `engine` holds `scene` already (a sweep
// keeps one engine for every case); `sceneName` goes under the title.
SurfacesPlot plotSurfaces(const Scene& scene, IlluminanceEngine& engine, const PlotOptions& options,
                          const std::string& sceneName, const std::filesystem::path& directory);

// The automatic top of the surfaces' legend: a round value at or above the 98th percentile of the
// positive values (a bright spot under a window must not leave the rest of the room dark).
double surfaceLegendTop(std::vector<double> illuminance);

}  // namespace penumbra::viz
