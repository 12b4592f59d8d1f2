#include "viz/surfaces_plot.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "viz/surface_field.hpp"
#include "viz/surface_sampling.hpp"
#include "viz/surfaces_view.hpp"
#include "viz/xml_files.hpp"

namespace penumbra::viz {

double surfaceLegendTop(std::vector<double> illuminance) {
  std::erase_if(illuminance, [](double e) { return !(e > 0.0); });
  if (illuminance.empty()) return 1.0;
  const auto k = static_cast<std::size_t>(0.98 * static_cast<double>(illuminance.size() - 1));
  std::nth_element(illuminance.begin(), illuminance.begin() + k, illuminance.end());
  return illuminance[k];
}

SurfacesPlot plotSurfaces(const Scene& scene, const PointLight& light, const std::string& lightName,
                          const PlotOptions& options, const std::string& sceneName,
                          const std::filesystem::path& directory) {
  SurfacesPlot result;
  result.spacing =
      options.surfaceSpacing > 0.0 ? options.surfaceSpacing : autoSurfaceSpacing(scene);
  const SurfaceMesh mesh = sampleSurfaces(scene, result.spacing);
  result.points = mesh.points.size();

  const std::vector<double> illuminance = light(mesh.points);
  const vtkSmartPointer<vtkPolyData> surfaces = surfacePolyData(scene, mesh, illuminance);
  writePolyDataFile(surfaces, directory / "surfaces.vtp");

  SurfacesStyle style;
  double darkest = INFINITY;  // lit: the bottom of a log legend
  for (double e : illuminance) {
    if (e > 0.0) darkest = std::min(darkest, e);
  }
  style.scale = colourScale(options.legend, darkest, surfaceLegendTop(illuminance));
  style.width = options.width;
  style.subtitle =
      fmt::format("{} · faces sampled every {} m ({} points) · E {} · L = ρ·E/π in surfaces.vtp",
                  sceneName, result.spacing, result.points, lightName);
  result.width = style.width;
  result.height = drawSurfaces(scene, surfaces, style, directory / "surfaces.png");
  return result;
}

}  // namespace penumbra::viz
