#include "study/case_renders.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "output/render_files.hpp"
#include "output/sweep_files.hpp"
#include "study/study.hpp"
#include "tonemap/tone_map.hpp"

namespace penumbra {

std::string renderDisplayName(const ToneMapOptions& display) {
  const ToneMapOptions standard;
  if (display.displayLuminance == standard.displayLuminance && display.ambient == standard.ambient)
    return "";
  return fmt::format("display={}cd/m2,ambient={}lx", display.displayLuminance, display.ambient);
}

CaseRenders::CaseRenders(std::vector<std::string> views, EstimatorOptions estimator,
                         std::string exposure, std::filesystem::path output,
                         const ToneMapOptions& display)
    : views_(std::move(views)),
      estimator_(std::move(estimator)),
      exposureText_(std::move(exposure)),
      exposure_(parseRenderExposure(exposureText_)),
      output_(std::move(output)) {
  display_.displayLuminance = display.displayLuminance;
  display_.ambient = display.ambient;
  if (exposure_.fixed()) display_.method = DisplayMethod::Clip;
  display_.white = exposure_.white;
  if (exposure_.autoFirst) {
    // A white chosen by an earlier run into this folder.
    std::ifstream in(output_ / kExposureJson);
    const nlohmann::json kept = nlohmann::json::parse(in, nullptr, false);
    if (kept.is_object() && kept.value("white_cdm2", 0.0) > 0) display_.white = kept["white_cdm2"];
  }
}
CaseRenders::~CaseRenders() = default;

std::string CaseRenders::name() const {
  return renderOutputName(views_, exposureText_, renderDisplayName(display_));
}

ToneMapOptions CaseRenders::displayFor(const RenderedView& rendered) {
  if (!exposure_.autoFirst || display_.white > 0) return display_;
  ToneMapOptions automatic = display_;  // clip with its automatic exposure: the white it chose
  ToneMapStats stats;
  displayValues(rendered.luminance, rendered.faces, automatic, &stats);
  display_.white = stats.white;
  writeTextFiles(
      output_,
      {{kExposureJson,
        nlohmann::json{{"exposure", "auto-first"}, {"white_cdm2", display_.white}}.dump(2) +
            "\n"}});
  return display_;
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
  renders.displayLuminance = display_.displayLuminance;
  renders.ambient = display_.ambient;
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
    DisplayImage display =
        toneMap(rendered.luminance, rendered.faces, displayFor(rendered), &stats);
    renders.views.push_back({std::move(rendered), std::move(display), stats});
  }
  return writeRenderFiles(renders, directory);
}

}  // namespace penumbra
