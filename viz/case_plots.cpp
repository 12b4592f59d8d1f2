#include "viz/case_plots.hpp"

#include <stdexcept>
#include <utility>

#include "viz/plot_files.hpp"
#include "viz/render_png.hpp"

namespace penumbra::viz {

CasePlots::CasePlots(PlotOptions options) : options_(std::move(options)) {}

CasePlots::~CasePlots() = default;

std::string CasePlots::unavailable() const {
  return displayUnavailable();
}

std::vector<std::string> CasePlots::write(const Scene& scene, const RunReport& report,
                                          const std::filesystem::path& directory) {
  bool current = false;  // estimator_ answers for this case's scene
  const PointLight light = [&](std::span<const SamplePoint> points) {
    if (!estimator_)
      estimator_ =
          std::make_unique<Estimator>(plotEstimatorOptions(report, options_.device), scene);
    else if (!current)
      estimator_->setScene(scene);  // the case's scene replaces the last one
    current = true;
    return estimator_->illuminance(points).total;
  };
  std::vector<std::string> images;
  for (const PlotFile& file : drawPlots(report, scene, light, options_, directory)) {
    if (file.image) images.push_back(file.name);
  }
  return images;
}

}  // namespace penumbra::viz
