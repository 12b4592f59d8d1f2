#pragma once
// Reads a photometric file by its extension: .ies (IES LM-63) or .ldt (EULUMDAT), in any case.
#include <filesystem>

#include "photometry/photometric_data.hpp"

namespace penumbra::photometry {

// PhotometricError for an unknown extension, an unreadable file or malformed content.
PhotometricData readPhotometricFile(const std::filesystem::path& file);

}  // namespace penumbra::photometry
