#include "study/study_exposure.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "output/image_files.hpp"
#include "output/sweep_files.hpp"
#include "output/tone_map_files.hpp"
#include "study/case_renders.hpp"
#include "tonemap/tone_map.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// One rendered view of a case: its luminance, face ids and display PNG, and the display the PNG
// is for (from render.json).
struct CasePicture {
  fs::path luminance, faces, png;
  double displayLuminance = 100.0, ambient = 0.0;
};

std::vector<CasePicture> studyPictures(const fs::path& out, const StudyLayout& layout) {
  std::vector<CasePicture> pictures;
  for (const PlannedCase& c : layout.cases) {
    const fs::path folder = out / kCasesFolder / c.id;
    std::ifstream in(folder / "render.json");
    if (!in) continue;  // not finished (a shard's other cases), or no renders
    const nlohmann::json render = nlohmann::json::parse(in, nullptr, false);
    if (!render.is_object()) continue;
    for (const nlohmann::json& view : render.value("views", nlohmann::json::array())) {
      const nlohmann::json& files = view.at("files");
      pictures.push_back({folder / files.at("luminance_exr").get<std::string>(),
                          folder / files.at("faceid_exr").get<std::string>(),
                          folder / files.at("display_png").get<std::string>(),
                          render.value("display_luminance_cdm2", ToneMapOptions{}.displayLuminance),
                          render.value("ambient_lx", ToneMapOptions{}.ambient)});
    }
  }
  return pictures;
}

ToneMapOptions clipDisplay(double white, const CasePicture& picture) {
  ToneMapOptions options;
  options.method = DisplayMethod::Clip;
  options.white = white;  // 0: automatic
  options.displayLuminance = picture.displayLuminance;
  options.ambient = picture.ambient;
  return options;
}

// The PNG's header: the view's penumbra:* lines as its .exr has them, for display values.
ImageMetadata pngMetadata(const fs::path& exr, double white) {
  ImageMetadata metadata;
  for (const auto& [key, value] : readImageMetadata(exr)) {
    if (key.rfind("penumbra:", 0) != 0) continue;
    metadata.emplace_back(
        key, key == "penumbra:units" ? "sRGB code values of display luminance" : value);
  }
  metadata.emplace_back("penumbra:exposure", fmt::format("auto-all, white {} cd/m2", white));
  return metadata;
}

}  // namespace

bool exposedAsOne(const StudyLayout& layout) {
  return std::any_of(layout.caseOutputs.begin(), layout.caseOutputs.end(),
                     [](const std::string& name) {
                       const std::string tail = " exposure=auto-all";
                       return name.size() > tail.size() &&
                              name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
                     });
}

StudyExposure exposeStudyRenders(const fs::path& out, const StudyLayout& layout) {
  const std::vector<CasePicture> pictures = studyPictures(out, layout);
  StudyExposure exposure;
  if (pictures.empty()) return exposure;
  double logSum = 0;
  for (const CasePicture& p : pictures) {
    ToneMapStats stats;
    displayValues(readRgbExr(p.luminance), readFaceIdExr(p.faces), clipDisplay(0, p), &stats);
    logSum += std::log(stats.white);
  }
  exposure.white = std::exp(logSum / static_cast<double>(pictures.size()));
  exposure.pictures = static_cast<int>(pictures.size());
  for (const CasePicture& p : pictures) {
    ToneMapStats stats;
    const DisplayImage display = toneMap(readRgbExr(p.luminance), readFaceIdExr(p.faces),
                                         clipDisplay(exposure.white, p), &stats);
    writeToneMapFiles(p.png, display, stats, pngMetadata(p.luminance, exposure.white));
  }
  writeTextFiles(out, {{kExposureJson, nlohmann::json{{"exposure", "auto-all"},
                                                      {"white_cdm2", exposure.white},
                                                      {"pictures", exposure.pictures}}
                                               .dump(2) +
                                           "\n"}});
  return exposure;
}

}  // namespace penumbra
