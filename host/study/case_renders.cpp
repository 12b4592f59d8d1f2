#include "study/case_renders.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "output/render_files.hpp"
#include "study/study.hpp"
#include "tonemap/tone_map.hpp"

namespace penumbra {

CaseRenders::CaseRenders(std::vector<std::string> views, EstimatorOptions estimator,
                         ToneMapOptions display)
    : views_(std::move(views)), estimator_(std::move(estimator)), display_(display) {}
CaseRenders::~CaseRenders() = default;

std::string CaseRenders::name() const {
  return renderOutputName(views_);
}

std::vector<std::string> CaseRenders::write(const Scene& scene, const RunReport& report,
                                            const std::filesystem::path& directory) {
  if (!device_)
    device_ = std::make_unique<compute::Device>(compute::Device::select(estimator_.device));
  // The program is built once per sweep; each case's scene replaces the previous one.
  if (renderer_) {
    renderer_->setScene(scene);
  } else {
    renderer_ = std::make_unique<Renderer>(
        *device_, scene, EngineOptions{estimator_.culling},
        estimator_.interreflection ? std::optional(estimator_.mesh) : std::nullopt);
  }
  RenderReport renders;
  renders.version = report.version;
  renders.sceneFile = report.sceneFile;
  renders.parameters = report.parameters;
  renders.device = report.device;
  renders.display = displayMethodName(display_.method);
  if (const InterreflectionReport* solved = renderer_->interreflection())
    renders.interreflection = *solved;
  renders.luminaires = report.luminaires;
  for (const std::string& name : views_) {
    const auto view = std::find_if(scene.views.begin(), scene.views.end(),
                                   [&](const View& v) { return v.name == name; });
    if (view == scene.views.end()) {
      throw std::runtime_error(fmt::format("the case's scene has no view '{}'", name));
    }
    RenderedView rendered = renderer_->render(*view, RenderOptions{1, 1, {}});
    ToneMapStats stats;
    DisplayImage display = toneMap(rendered.luminance, rendered.faces, display_, &stats);
    renders.views.push_back({std::move(rendered), std::move(display), stats});
  }
  return writeRenderFiles(renders, directory);
}

}  // namespace penumbra
