#pragma once
// What `penumbra tonemap` (and `penumbra render --display ...`) write for one view: the PNG of
// display values and, beside it, the solver's statistics as JSON (<stem>.tonemap.json).
#include <filesystem>

#include <nlohmann/json.hpp>

#include "image/images.hpp"
#include "tonemap/tone_map_options.hpp"

namespace penumbra {

nlohmann::json toneMapStatsJson(const ToneMapStats& stats);

// out/from-door.png → out/from-door.tonemap.json
std::filesystem::path toneMapStatsPath(const std::filesystem::path& png);

// The PNG holds sRGB code values of the display luminance the tone map asks for on its target
// display (tonemap/display_model.hpp), tagged sRGB (the sRGB, gAMA and cHRM chunks); the method,
// the display, black level and weights go into its text chunks.
ImageMetadata toneMapPngMetadata(const ToneMapStats& stats);

// Writes the PNG (with `metadata` added to the tone map's own) and the JSON beside it.
void writeToneMapFiles(const std::filesystem::path& png, const DisplayImage& image,
                       const ToneMapStats& stats, const ImageMetadata& metadata = {});

}  // namespace penumbra
