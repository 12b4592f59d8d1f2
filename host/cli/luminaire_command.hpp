#pragma once
// `penumbra luminaire FILE [--ugr-table [-o DIR]]`: what a photometric file (IES LM-63 or EULUMDAT)
// holds, read as penumbra reads it: format, type, symmetry, lamps, LOR, opening, peak intensity and
// the flux of the table against the file's; with --ugr-table the luminaire's UGR table by the CIE
// 190 tabular method (glare/ugr_table.hpp).
#include <filesystem>
#include <string>

#include "photometry/light_distribution.hpp"
#include "photometry/photometric_data.hpp"

namespace penumbra {

struct LuminaireOptions {
  std::filesystem::path file;
  bool ugrTable = false;                  // print the CIE 190 UGR table
  std::filesystem::path outputDirectory;  // with ugrTable: its CSV goes here (empty: none)
};

// The report printed for `file`.
std::string describeLuminaire(const std::filesystem::path& file,
                              const photometry::PhotometricData& data,
                              const photometry::LightDistribution& distribution);

// Exit status 0, 2 for a malformed file (file:line: field: message), 1 for an unreadable one
// or, with --ugr-table, a luminaire without a flat luminous area or a CSV that cannot be written.
int runLuminaireCommand(const LuminaireOptions& options);

}  // namespace penumbra
