#pragma once
// The command-line options of `penumbra tonemap` (CLI11), kept beside main.cpp so that main()
// only registers and dispatches.
#include <CLI/CLI.hpp>

#include "cli/display_options.hpp"
#include "cli/help_text.hpp"
#include "cli/tonemap_command.hpp"

namespace penumbra::cli {

inline CLI::App* addToneMapCommand(CLI::App& app, ToneMapCommandOptions& options) {
  CLI::App* command = app.add_subcommand("tonemap", help::kToneMap);
  command->footer(help::kToneMapFooter);
  command->add_option("input", options.input, "HDR image (<view>.exr, linear RGB in cd/m2)")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--faces", options.faces,
                      "Face ids (<view>.faceid.exr; default: beside the input under that name)");
  command->add_option("-o,--output", options.output, "PNG to write")->required();
  addDisplayOptions(*command, options.display);
  command->add_flag("-v,--verbose", options.verbose, "Print the solver's statistics");
  return command;
}

}  // namespace penumbra::cli
