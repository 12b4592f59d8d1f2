#pragma once
// `penumbra luminaire FILE`: what a photometric file (IES LM-63 or EULUMDAT) holds, read as
// penumbra reads it: format, type, symmetry, lamps, LOR, opening, peak intensity and the flux
// of the table against the file's.
#include <filesystem>
#include <string>

#include "photometry/light_distribution.hpp"
#include "photometry/photometric_data.hpp"

namespace penumbra {

struct LuminaireOptions {
  std::filesystem::path file;
};

// The report printed for `file`.
std::string describeLuminaire(const std::filesystem::path& file,
                              const photometry::PhotometricData& data,
                              const photometry::LightDistribution& distribution);

// Exit status 0, 2 for a malformed file (file:line: field: message), 1 for an unreadable one.
int runLuminaireCommand(const LuminaireOptions& options);

}  // namespace penumbra
