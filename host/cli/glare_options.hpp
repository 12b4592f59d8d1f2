#pragma once
// The command-line options of `penumbra glare` (CLI11), kept beside main.cpp so that main()
// only registers and dispatches.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/glare_command.hpp"
#include "cli/help_text.hpp"
#include "cli/option_checks.hpp"

namespace penumbra::cli {

inline CLI::App* addGlareCommand(CLI::App& app, GlareOptions& options,
                                 std::vector<std::string>& settings) {
  CLI::App* command = app.add_subcommand("glare", help::kGlare);
  command->footer(help::kGlareFooter);
  command->add_option("scene", options.scene, "Scene file (YAML, scene format v1) with observers")
      ->required();
  command->add_option("-o,--output", options.output, "Output directory (created if missing)")
      ->required();
  addDeviceOption(*command, options.estimator.device);
  addInterreflectionOptions(*command, options.estimator);
  command
      ->add_option("--set", settings,
                   "Give a scene parameter a value other than its default: NAME=VALUE (repeat "
                   "for several)")
      ->allow_extra_args(false)
      ->check(kParameterAssignment);
  command->add_flag("-q,--quiet", options.quiet, "No progress and no table; errors only");
  return command;
}

}  // namespace penumbra::cli
