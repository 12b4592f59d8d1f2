#pragma once
// The command-line options of `penumbra luminaire` (CLI11), kept beside main.cpp so that main()
// only registers and dispatches.
#include <CLI/CLI.hpp>

#include "cli/help_text.hpp"
#include "cli/luminaire_command.hpp"

namespace penumbra::cli {

inline CLI::App* addLuminaireCommand(CLI::App& app, LuminaireOptions& options) {
  CLI::App* command = app.add_subcommand("luminaire", help::kLuminaire);
  command->footer(help::kLuminaireFooter);
  command->add_option("file", options.file, "Photometric file: .ies (IES LM-63) or .ldt (EULUMDAT)")
      ->required();
  command->add_flag("--ugr-table", options.ugrTable,
                    "Print the CIE 190 UGR table of the luminaire (S = 0.25H and 1.0H, H = 2 m)");
  command->add_option("-o,--output", options.outputDirectory,
                      "With --ugr-table: write <file stem>-ugr-table.csv into this directory");
  return command;
}

}  // namespace penumbra::cli
