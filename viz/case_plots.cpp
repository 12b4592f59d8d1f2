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
  const SurfaceEngine surfaceEngine = [&]() -> IlluminanceEngine& {
    if (!engine_) {
      device_ = std::make_unique<compute::Device>(compute::Device::select(options_.device));
      engine_ = std::make_unique<IlluminanceEngine>(*device_, scene);
    } else {
      engine_->setScene(scene);  // asked once per case: the case's scene replaces the last one
    }
    return *engine_;
  };
  std::vector<std::string> images;
  for (const PlotFile& file : drawPlots(report, scene, surfaceEngine, options_, directory)) {
    if (file.image) images.push_back(file.name);
  }
  return images;
}

}  // namespace penumbra::viz
