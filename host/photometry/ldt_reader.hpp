#pragma once
// EULUMDAT (.ldt) photometric files: one field a line, intensities in cd/klm
// (docs/photometry.md). Every malformed file is one PhotometricError naming the line and field.
#include <filesystem>
#include <string_view>

#include "photometry/photometric_data.hpp"

namespace penumbra::photometry {

// The counts a EULUMDAT file may declare: C planes in 0.1° steps, γ angles in 0.1° steps, lamp
// sets.
inline constexpr int kMaxLdtCPlanes = 3600;
inline constexpr int kMaxLdtGammaAngles = 1801;
inline constexpr int kMaxLdtLampSets = 100;

// Reads the text of a EULUMDAT file; `file` names it in messages.
PhotometricData parseLdt(std::string_view text, const std::filesystem::path& file);

}  // namespace penumbra::photometry
