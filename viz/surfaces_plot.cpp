#include "viz/surfaces_plot.hpp"

#include <fmt/format.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

double surfaceSpacing(const Scene& scene, const PlotOptions& options) {
  return options.surfaceSpacing > 0.0 ? options.surfaceSpacing : autoSurfaceSpacing(scene);
}

SurfacesPlot writeSurfacesFile(const Scene& scene, const PointLight& light,
                               const PlotOptions& options, const std::filesystem::path& directory) {
  SurfacesPlot result;
  result.spacing = surfaceSpacing(scene, options);
  const SurfaceMesh mesh = sampleSurfaces(scene, result.spacing);
  result.points = mesh.points.size();
  const std::vector<double> illuminance = light(mesh.points);
  writePolyDataFile(surfacePolyData(scene, mesh, illuminance), directory / "surfaces.vtp");
  return result;
}

int drawSurfacesPicture(const Scene& scene, const std::filesystem::path& surfacesFile,
                        const std::string& lightName, const PlotOptions& options,
                        const std::string& sceneName, const std::filesystem::path& png) {
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(surfacesFile.string().c_str());
  reader->Update();
  vtkPolyData* surfaces = reader->GetOutput();
  vtkDataArray* e = surfaces->GetPointData()->GetArray("E_lx");
  if (reader->GetErrorCode() != 0 || e == nullptr) {
    throw std::runtime_error(fmt::format("cannot read {} (E_lx)", surfacesFile.string()));
  }
  std::vector<double> illuminance(static_cast<std::size_t>(e->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < e->GetNumberOfTuples(); ++i) illuminance[i] = e->GetTuple1(i);

  SurfacesStyle style;
  double darkest = INFINITY;  // lit: the bottom of a log legend
  for (double value : illuminance) {
    if (value > 0.0) darkest = std::min(darkest, value);
  }
  style.scale = colourScale(options.legend, darkest, surfaceLegendTop(illuminance));
  style.width = options.width;
  style.subtitle =
      fmt::format("{} · faces sampled every {} m ({} points) · E {} · L = ρ·E/π in surfaces.vtp",
                  sceneName, surfaceSpacing(scene, options), illuminance.size(), lightName);
  return drawSurfaces(scene, surfaces, style, png);
}

}  // namespace penumbra::viz
