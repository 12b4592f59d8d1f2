#pragma once
// The room's surfaces in false colour: sample every face, compute E there with the OpenCL
// engine (with the interreflected light where the run has it), write surfaces.vtp and render
// surfaces.png.
#include <filesystem>
#include <string>

#include "scene/scene.hpp"
#include "viz/plot_options.hpp"
#include "viz/point_light.hpp"

namespace penumbra::viz {

struct SurfacesPlot {
  double spacing = 0.0;  // m, as used
  std::size_t points = 0;
  int width = 0, height = 0;  // of the PNG, px
};

// Writes surfaces.vtp and surfaces.png into `directory`. `light` answers for `scene`;
// `lightName` says what it includes ("total (direct + interreflected)", "direct light only") and
// goes under the title with `sceneName`.
SurfacesPlot plotSurfaces(const Scene& scene, const PointLight& light, const std::string& lightName,
                          const PlotOptions& options, const std::string& sceneName,
                          const std::filesystem::path& directory);

// The automatic top of the surfaces' legend: a round value at or above the 98th percentile of the
// positive values (a bright spot under a window must not leave the rest of the room dark).
double surfaceLegendTop(std::vector<double> illuminance);

}  // namespace penumbra::viz
