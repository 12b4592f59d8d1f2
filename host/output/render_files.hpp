#pragma once
// The files of a `penumbra render` run, in one output directory, per view:
//   <view>.exr          luminance, linear RGB, 32-bit float, cd/m²
//   <view>.hdr          the same as Radiance RGBE (for Radiance tools and HDR viewers)
//   <view>.E.exr        illuminance at each pixel's visible point, channel "E", lx
//   <view>.faceid.exr   which face each pixel shows, channel "id" (render/visible_scene.hpp)
//   <view>.png          the display image (host/tonemap), <view>.tonemap.json its statistics
// and render.json: scene, parameters, device, options and per view its camera and statistics.
// The view, scene and units, what light the images include ("penumbra:light": "total (direct +
// interreflected)" or "direct only") and the luminaires' maintenance factors are also written
// into each image's header ("penumbra:*").
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grid/run_report.hpp"
#include "image/images.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "tonemap/tone_map_options.hpp"

namespace penumbra {

struct RenderReport {
  std::string version;
  std::filesystem::path sceneFile;
  ParameterValues parameters;
  std::string device;
  int interval = 1, spp = 1;
  std::string display;  // how the PNG was made
  // The display the PNG is encoded for (tonemap/display_model.hpp): white in cd/m², lx on it.
  double displayLuminance = 100.0, ambient = 0.0;
  // The interreflection solver's report; empty when the images show direct light only.
  std::optional<InterreflectionReport> interreflection;
  std::vector<LuminaireReport> luminaires;  // the scene's photometric luminaires
  struct ViewFiles {
    RenderedView rendered;
    DisplayImage display;
    ToneMapStats toneMap;  // how `display` was made
  };
  std::vector<ViewFiles> views;
  double totalSeconds = 0.0;
};

// The file name stem of a view (its name, with characters outside [A-Za-z0-9._-] replaced).
std::string viewFileStem(const std::string& viewName);
nlohmann::json renderJson(const RenderReport& report);
// Writes every file into the existing `directory` as it is (a sweep's case folder is staged as a
// whole by its caller). Returns the display images' file names.
std::vector<std::string> writeRenderFiles(const RenderReport& report,
                                          const std::filesystem::path& directory);
// Writes every file into `directory` atomically (StagedDirectory): all or none.
// `more` may add files to the staging folder before it is committed (the vector drawings).
void writeRenders(const RenderReport& report, const std::filesystem::path& directory,
                  const std::function<void(const std::filesystem::path&)>& more = {});

}  // namespace penumbra
