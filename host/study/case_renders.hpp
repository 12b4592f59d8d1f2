#pragma once
// The per-case renders of a sweep (`renders: [view, ...]` in a study file): each case's views
// rendered exactly (interval 1) and tone-mapped, written into the case's staged folder through
// the sweep runner's output hook (output/case_output.hpp), as `penumbra render` writes them.
#include <memory>
#include <string>
#include <vector>

#include "cl/device.hpp"
#include "illuminance/estimator.hpp"
#include "output/case_output.hpp"
#include "render/renderer.hpp"
#include "study/render_exposure.hpp"
#include "tonemap/tone_map_options.hpp"

namespace penumbra {

// Where auto-first keeps the white it chose (OUT/exposure.json), so that a rerun or --resume
// exposes the cases it adds as the first ones were.
inline constexpr const char* kExposureJson = "exposure.json";

// The target display as the renders' output name gives it: "" for the default display (100
// cd/m², no ambient light), otherwise "display=200cd/m2,ambient=500lx".
std::string renderDisplayName(const ToneMapOptions& display);

class CaseRenders : public CaseOutputWriter {
 public:
  // The device as --device takes it (opened at the first case and kept), culling, and whether
  // the images include the interreflected light, on which mesh, as the sweep's grids do.
  // `exposure` as `sweep --exposure` takes it (render_exposure.hpp); `output` is the sweep's
  // folder (where auto-first keeps its white).
  // `display` gives the target display (displayLuminance, ambient; its other fields are not
  // used: the exposure decides the map).
  CaseRenders(std::vector<std::string> views, EstimatorOptions estimator, std::string exposure = "",
              std::filesystem::path output = {}, const ToneMapOptions& display = {});
  ~CaseRenders() override;

  std::string name() const override;
  // Returns the display PNGs, one per view.
  std::vector<std::string> write(const Scene& scene, const RunReport& report,
                                 const std::filesystem::path& directory) override;

 private:
  // The display of this case's views: the study's white, chosen from `rendered` (the first
  // view) when auto-first has none yet.
  ToneMapOptions displayFor(const RenderedView& rendered);

  std::vector<std::string> views_;
  EstimatorOptions estimator_;
  std::string exposureText_;
  RenderExposure exposure_;
  std::filesystem::path output_;
  ToneMapOptions display_;
  std::unique_ptr<compute::Device> device_;
  std::unique_ptr<Renderer> renderer_;
};

}  // namespace penumbra
