#include "viz/case_plots.hpp"

#include <stdexcept>
#include <utility>

#include "output/result_reader.hpp"
#include "viz/plot_files.hpp"
#include "viz/plot_pictures.hpp"
#include "viz/render_png.hpp"

namespace penumbra::viz {

CasePlots::CasePlots(PlotOptions options) : options_(std::move(options)) {}

CasePlots::~CasePlots() = default;

std::string CasePlots::unavailable() const {
  return displayUnavailable();
}

std::vector<std::string> CasePlots::write(const Scene& scene, const RunReport& /*report*/,
                                          const std::filesystem::path& directory) {
  // The case's files are written: drawn from them, as `penumbra plot` draws a folder, the plots
  // show E with the digits the files hold and are those of `penumbra grid --plot` on the case.
  const RunReport written = readResults(directory);
  bool current = false;  // estimator_ answers for this case's scene
  const PointLight light = [&](std::span<const SamplePoint> points) {
    if (!estimator_)
      estimator_ =
          std::make_unique<Estimator>(plotEstimatorOptions(written, options_.device), scene);
    else if (!current)
      estimator_->setScene(scene);  // the case's scene replaces the last one
    current = true;
    return estimator_->illuminance(points).total;
  };
  std::vector<std::string> images;
  for (const PlotFile& file : writePlotData(written, scene, light, options_, directory)) {
    if (file.image) images.push_back(file.name);
  }
  for (PictureFile& png : plotPictures(written, scene, options_, directory)) {
    images.push_back(std::move(png.fileName));
  }
  return images;
}

PicturesWritten CasePlots::drawPictures(const Scene& scene,
                                        const std::filesystem::path& directory) {
  return drawPlotPictures(readResults(directory), scene, options_, directory);
}

}  // namespace penumbra::viz
