#include "output/tone_map_files.hpp"

#include <fmt/format.h>

#include <ostream>

#include "output/image_files.hpp"
#include "output/result_files.hpp"

namespace penumbra {

nlohmann::json toneMapStatsJson(const ToneMapStats& s) {
  nlohmann::json residual = {
      {"strong", {{"rows", s.strongRows}, {"rms", s.strongRms}, {"max", s.strongMax}}},
      {"medium", {{"rows", s.mediumRows}, {"rms", s.mediumRms}, {"max", s.mediumMax}}},
      {"weak", {{"rows", s.weakRows}, {"rms", s.weakRms}, {"max", s.weakMax}}},
  };
  return {
      {"method", s.method},
      {"black", s.black},
      {"white_cdm2", s.white},
      {"display_luminance_cdm2", s.displayLuminance},
      {"ambient_lx", s.ambient},
      {"reflectivity", DisplayModel::kReflectivity},
      {"lower_bound", s.lowerBound},
      {"weights", {{"strong", s.strong}, {"medium", s.medium}, {"weak", s.weak}}},
      {"vertices", s.vertices},
      {"lattice_px", s.lattice},
      {"width", s.width},
      {"height", s.height},
      {"regions", s.regions},
      {"variables", s.variables},
      {"rows", s.strongRows + s.mediumRows + s.weakRows},
      {"three_variable_rows", s.threeVariableRows},
      {"outer_iterations", s.outerIterations},
      {"active_set_iterations", s.activeSetIterations},
      {"projected_newton_iterations", s.projectedNewtonIterations},
      {"converged", s.converged},
      {"at_lower_bound", s.atLowerBound},
      {"at_upper_bound", s.atUpperBound},
      {"raised_to_white_log", s.raisedToWhite},
      {"residual", residual},
      {"seconds",
       {{"build", s.buildSeconds},
        {"solve", s.solveSeconds},
        {"pixels", s.pixelSeconds},
        {"total", s.totalSeconds}}},
  };
}

std::filesystem::path toneMapStatsPath(const std::filesystem::path& png) {
  std::filesystem::path json = png;
  return json.replace_extension(".tonemap.json");
}

ImageMetadata toneMapPngMetadata(const ToneMapStats& s) {
  return {
      // OpenImageIO writes the PNG's sRGB chunk with gAMA and cHRM for this colour space.
      {"oiio:ColorSpace", "sRGB"},
      {"penumbra:values",
       "sRGB code values: the display luminance each pixel is meant to show on the display "
       "below, through its model L = (Lmax - Lblack) sRGB(V) + Lblack + k E_amb / pi"},
      {"penumbra:display", s.method},
      {"penumbra:black", fmt::format("{}", s.black)},
      {"penumbra:display_luminance", fmt::format("{} cd/m2", s.displayLuminance)},
      {"penumbra:ambient",
       fmt::format("{} lx, reflectivity {}", s.ambient, DisplayModel::kReflectivity)},
      {"penumbra:lower_bound", fmt::format("{}", s.lowerBound)},
      {"penumbra:weights", fmt::format("strong={} medium={} weak={}", s.strong, s.medium, s.weak)},
      {"penumbra:vertices", s.vertices},
      {"penumbra:lattice", fmt::format("{}", s.lattice)},
      {"penumbra:white", fmt::format("{} cd/m2", s.white)},
  };
}

void writeToneMapFiles(const std::filesystem::path& png, const DisplayImage& image,
                       const ToneMapStats& stats, const ImageMetadata& metadata) {
  ImageMetadata all = toneMapPngMetadata(stats);
  all.insert(all.end(), metadata.begin(), metadata.end());
  writePng(png, image, all);
  writeFile(toneMapStatsPath(png),
            [&](std::ostream& out) { out << toneMapStatsJson(stats).dump(2) << "\n"; });
}

}  // namespace penumbra
