#pragma once
// `penumbra sweep` and `penumbra merge`: a study file in, a folder of cases, tables and charts
// out (docs/sweeps.md). Kept free of CLI11, like grid_command.hpp.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "output/sweep_files.hpp"
#include "tonemap/tone_map_options.hpp"

namespace penumbra {

struct SweepOptions {
  std::filesystem::path study;
  std::filesystem::path output;
  EstimatorOptions estimator;  // as for `penumbra grid`
  std::string shard;           // "i/N"; empty: every case
  bool resume = false;
  bool quiet = false;
  // --slurm: submit the shards to Slurm instead of computing (docs/cluster.md).
  bool slurm = false;
  int shards = 0;                         // --shards N; 0: with --resume, as submitted
  std::vector<std::string> slurmOptions;  // --slurm-opt, each split into words
  bool dryRun = false;
  // --exposure for the renders: "" (each case on its own), a white in cd/m², or "auto-first".
  std::string exposure;
  // --display-luminance and --ambient for the renders (only those two fields are used).
  ToneMapOptions renderDisplay;
  ChartWriter charts;  // set by main() when the binary has viz/
  std::vector<std::shared_ptr<CaseOutputWriter>> caseOutputs;  // likewise (per-case plots)
};

struct MergeOptions {
  std::vector<std::filesystem::path> inputs;
  std::filesystem::path output;
  bool quiet = false;
  ChartWriter charts;
};

// Exit status: 0 done (with --slurm: submitted, or written with --dry-run); 1 error (device,
// files, options, --resume without a run to resume, sbatch missing or refusing); 2 the study or
// the scene of one of its cases is invalid (nothing is written or submitted then).
int runSweepCommand(const SweepOptions& options);
// Exit status: 0 done; 1 error (not sweep folders, different studies, files).
int runMergeCommand(const MergeOptions& options);

}  // namespace penumbra
