#include "output/render_files.hpp"

#include <fmt/format.h>

#include <set>
#include <stdexcept>

#include "output/image_files.hpp"
#include "output/result_files.hpp"
#include "output/staged_directory.hpp"
#include "output/tone_map_files.hpp"

namespace penumbra {
namespace {

std::string vec3Text(const Vec3& v) {
  return fmt::format("{} {} {}", v.x(), v.y(), v.z());
}

nlohmann::json vec3Json(const Vec3& v) {
  return nlohmann::json::array({v.x(), v.y(), v.z()});
}

// "name=0.8, other=1": the factor each photometric luminaire's flux is scaled by.
std::string maintenanceFactors(const std::vector<LuminaireReport>& luminaires) {
  std::string text;
  for (const LuminaireReport& l : luminaires)
    text += fmt::format("{}{}={}", text.empty() ? "" : ", ", l.name, l.maintenanceFactor);
  return text;
}

// What every image of a view carries in its header.
ImageMetadata viewMetadata(const RenderReport& report, const View& view, const std::string& units) {
  ImageMetadata metadata{
      {"penumbra:version", report.version},
      {"penumbra:scene", report.sceneFile.string()},
      {"penumbra:parameters", describeParameters(report.parameters)},
      {"penumbra:view", view.name},
      {"penumbra:eye_m", vec3Text(view.eye)},
      {"penumbra:target_m", vec3Text(view.target)},
      {"penumbra:up", vec3Text(view.up)},
      {"penumbra:fov_deg", fmt::format("{}", view.fovDegrees)},
      {"penumbra:interval", std::to_string(report.interval)},
      {"penumbra:spp", std::to_string(report.spp)},
      {"penumbra:light", illuminanceMeaning(report.interreflection.has_value(), report.luminaires)},
      {"penumbra:units", units}};
  if (!report.luminaires.empty())
    metadata.push_back({"penumbra:maintenance_factor", maintenanceFactors(report.luminaires)});
  return metadata;
}

// Radiance's convention (radiance_hdr.hpp): its tools multiply by 179 to give cd/m².
constexpr const char* kRadianceUnits = "W/(sr m2), radiance at 179 lm/W: cd/m2 = 179 x value";

}  // namespace

std::string viewFileStem(const std::string& viewName) {
  return safeFileStem(viewName, "view_");
}

nlohmann::json renderJson(const RenderReport& report) {
  nlohmann::json views = nlohmann::json::array();
  for (const RenderReport::ViewFiles& files : report.views) {
    const RenderedView& r = files.rendered;
    const RenderStats& s = r.stats;
    const std::string stem = viewFileStem(r.view.name);
    views.push_back({
        {"name", r.view.name},
        {"eye_m", vec3Json(r.view.eye)},
        {"target_m", vec3Json(r.view.target)},
        {"up", vec3Json(r.view.up)},
        {"fov_deg", r.view.fovDegrees},
        {"width_px", r.view.width},
        {"height_px", r.view.height},
        {"files",
         {{"luminance_exr", stem + ".exr"},
          {"luminance_hdr", stem + ".hdr"},
          {"illuminance_exr", stem + ".E.exr"},
          {"faceid_exr", stem + ".faceid.exr"},
          {"display_png", stem + ".png"},
          {"tone_map_json", stem + ".tonemap.json"}}},
        {"samples", s.samples},
        {"surface_samples", s.surfaceSamples},
        {"exact_samples", s.exactSamples},
        {"exact_share", s.exactShare()},
        {"gathered_samples", s.gatheredSamples},
        {"object_tests_per_sample", s.objectTestsPerSample},
        {"timing",
         {{"visibility_s", s.visibilitySeconds},
          {"illuminance_s", s.illuminanceSeconds},
          {"shading_s", s.shadingSeconds},
          {"indirect_s", s.indirectSeconds}}},
    });
  }
  nlohmann::json json = {
      {"penumbra_version", report.version},
      {"scene", report.sceneFile.string()},
      {"parameters", parameterJson(report.parameters)},
      {"device", report.device},
      {"interval", report.interval},
      {"spp", report.spp},
      {"display", report.display},
      {"display_luminance_cdm2", report.displayLuminance},
      {"ambient_lx", report.ambient},
      {"light", illuminanceMeaning(report.interreflection.has_value(), report.luminaires)},
      {"units", {{"luminance", "cd/m2"}, {"illuminance", "lx"}}},
      {"total_s", report.totalSeconds},
      {"views", views},
  };
  if (report.interreflection)
    json["interreflection"] = interreflectionJson(*report.interreflection);
  if (!report.luminaires.empty()) json["luminaires"] = luminairesJson(report.luminaires);
  return json;
}

std::vector<std::string> writeRenderFiles(const RenderReport& report,
                                          const std::filesystem::path& dir) {
  std::set<std::string> stems;
  for (const RenderReport::ViewFiles& files : report.views) {
    const std::string stem = viewFileStem(files.rendered.view.name);
    if (!stems.insert(stem).second) {
      throw std::runtime_error(fmt::format(
          "two views would be written to {}.exr; give them names that differ in letters or digits",
          stem));
    }
  }
  std::vector<std::string> displays;
  for (const RenderReport::ViewFiles& files : report.views) {
    const RenderedView& r = files.rendered;
    const std::string stem = viewFileStem(r.view.name);
    writeRgbExr(dir / (stem + ".exr"), r.luminance, viewMetadata(report, r.view, "cd/m2"));
    writeRadianceHdr(dir / (stem + ".hdr"), r.luminance,
                     RadianceHeader{r.view, "penumbra " + report.version,
                                    viewMetadata(report, r.view, kRadianceUnits)});
    writeScalarExr(dir / (stem + ".E.exr"), r.illuminance, "E", viewMetadata(report, r.view, "lx"));
    writeFaceIdExr(dir / (stem + ".faceid.exr"), r.faces,
                   viewMetadata(report, r.view, "face id (0: none)"));
    writeToneMapFiles(dir / (stem + ".png"), files.display, files.toneMap,
                      viewMetadata(report, r.view, "sRGB code values of display luminance"));
    displays.push_back(stem + ".png");
  }
  writeFile(dir / "render.json",
            [&](std::ostream& out) { out << renderJson(report).dump(2) << "\n"; });
  return displays;
}

void writeRenders(const RenderReport& report, const std::filesystem::path& directory,
                  const std::function<void(const std::filesystem::path&)>& more) {
  StagedDirectory staged(directory);
  writeRenderFiles(report, staged.staging());
  if (more) more(staged.staging());
  staged.commit();
}

}  // namespace penumbra
