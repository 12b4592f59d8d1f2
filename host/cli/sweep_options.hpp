#pragma once
// The command-line options of `penumbra sweep` and `penumbra merge` (CLI11), kept beside
// main.cpp so that main() only registers and dispatches.
#include <CLI/CLI.hpp>

#include "cli/display_options.hpp"
#include "cli/help_text.hpp"
#include "cli/option_checks.hpp"
#include "cli/sweep_command.hpp"

namespace penumbra::cli {

inline CLI::App* addSweepCommand(CLI::App& app, SweepOptions& options) {
  CLI::App* command = app.add_subcommand("sweep", help::kSweep);
  command->footer(help::kSweepFooter);
  command->add_option("study", options.study, "Study file (YAML, docs/sweeps.md)")->required();
  command->add_option("-o,--output", options.output, "Output folder (created if missing)")
      ->required();
  command->add_option("--shard", options.shard,
                      "Run only shard I of N: every N-th case, starting with case I (1 <= I <= N)");
  command->add_flag("--resume", options.resume,
                    "Continue a run into the output folder it used: fails unless the folder "
                    "holds this very study; computes what is missing, rebuilds the tables");
  addEstimatorOptions(*command, options.estimator);
  command->add_flag("-q,--quiet", options.quiet, "No progress and no summary; errors only");
  CLI::Option* slurm = command->add_flag(
      "--slurm", options.slurm,
      "Submit the study to Slurm instead of computing it: a job array of --shards tasks and a "
      "merge job that writes results.csv into OUT when every shard succeeded (docs/cluster.md)");
  command
      ->add_option("--shards", options.shards, "With --slurm: the number of shards (array tasks)")
      ->needs(slurm)
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--slurm-opt", options.slurmOptions,
                   "With --slurm: options for sbatch, e.g. \"--partition=compute "
                   "--time=00:30:00\" (repeat for more)")
      ->needs(slurm)
      ->allow_extra_args(false);
  command
      ->add_flag("--dry-run", options.dryRun,
                 "With --slurm: write the batch scripts into OUT/slurm and print the sbatch "
                 "commands, submit nothing")
      ->needs(slurm);
  command
      ->add_option("--exposure", options.exposure,
                   "Renders (`renders:`) with one fixed exposure for the whole study, so that "
                   "they compare: a luminance in cd/m2 shown as white, auto-first (the "
                   "automatic exposure of the first case rendered, kept for every other) or "
                   "auto-all (the automatic exposure of all the study's renders together: once "
                   "the cases are done, every PNG is exposed again with the geometric mean of "
                   "the pictures' automatic whites, kept in OUT/exposure.json)")
      ->check(kStudyExposure)
      ->excludes(slurm)
      ->type_name("CDM2|auto-first|auto-all");
  // The renders' target display; part of the renders' name, so that a case rendered for
  // another display is computed again and every case's PNG is for the same display.
  for (CLI::Option* option : addTargetDisplayOptions(*command, options.renderDisplay))
    option->excludes(slurm);
  return command;
}

inline CLI::App* addMergeCommand(CLI::App& app, MergeOptions& options) {
  CLI::App* command = app.add_subcommand("merge", help::kMerge);
  command->footer(help::kMergeFooter);
  command->add_option("folders", options.inputs, "Output folders of `penumbra sweep --shard`")
      ->required();
  command->add_option("-o,--output", options.output, "The joined folder (created if missing)")
      ->required();
  command->add_flag("-q,--quiet", options.quiet, "No summary; errors only");
  return command;
}

}  // namespace penumbra::cli
