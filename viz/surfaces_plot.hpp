#pragma once
// The room's surfaces in false colour: sample every face, compute E there with the OpenCL
// engine (with the interreflected light where the run has it) and write surfaces.vtp; then,
// from that file, render surfaces.png.
#include <filesystem>
#include <string>

#include "scene/scene.hpp"
#include "viz/plot_options.hpp"
#include "viz/point_light.hpp"

namespace penumbra::viz {

struct SurfacesPlot {
  double spacing = 0.0;  // m, as used
  std::size_t points = 0;
};

// The spacing of the samples on the faces: options.surfaceSpacing, or one from the scene's size.
double surfaceSpacing(const Scene& scene, const PlotOptions& options);

// Writes surfaces.vtp into `directory`. `light` answers for `scene`.
SurfacesPlot writeSurfacesFile(const Scene& scene, const PointLight& light,
                               const PlotOptions& options, const std::filesystem::path& directory);

// Renders surfaces.png into `png` from `surfacesFile` (as writeSurfacesFile wrote it for `scene`
// with `options`); needs a display. `lightName` says what E includes ("total (direct +
// interreflected)", "direct light only") and goes under the title with `sceneName`. Returns the
// height of the image in px. Throws std::runtime_error when the file cannot be read.
int drawSurfacesPicture(const Scene& scene, const std::filesystem::path& surfacesFile,
                        const std::string& lightName, const PlotOptions& options,
                        const std::string& sceneName, const std::filesystem::path& png);

// The automatic top of the surfaces' legend: a round value at or above the 98th percentile of the
// positive values (a bright spot under a window must not leave the rest of the room dark).
double surfaceLegendTop(std::vector<double> illuminance);

}  // namespace penumbra::viz
