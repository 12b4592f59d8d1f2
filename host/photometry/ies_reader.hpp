#pragma once
// IES LM-63 photometric files: LM-63-1986 (no version line), -1991, -1995, -2002 and -2019
// (docs/photometry.md). Every malformed file is one PhotometricError naming the line and field.
#include <filesystem>
#include <string_view>

#include "photometry/photometric_data.hpp"

namespace penumbra::photometry {

// The counts an IES file may declare: 0.1° steps over 180° and 360°.
inline constexpr int kMaxIesVerticalAngles = 1801;
inline constexpr int kMaxIesHorizontalAngles = 3601;

// Reads the text of an IES file; `file` names it in messages.
PhotometricData parseIes(std::string_view text, const std::filesystem::path& file);

}  // namespace penumbra::photometry
