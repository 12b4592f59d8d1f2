#pragma once
// `penumbra sweep --slurm`: hands a study's shards to Slurm instead of computing them
// (docs/cluster.md). Writes OUT/slurm/{sweep,merge}.sbatch, submits the job array and the merge
// (`--dependency=afterok:<array>`), and records both in OUT/slurm/submission.json so that
// `--resume` can resubmit only the shards that did not finish.
#include <filesystem>
#include <string>
#include <vector>

#include "illuminance/estimator.hpp"
#include "study/study.hpp"

namespace penumbra {

struct SlurmSettings {
  std::filesystem::path output;            // OUT
  int shards = 0;                          // N, 1 ≤ N ≤ cases; 0 with --resume: as submitted
  std::vector<std::string> sbatchOptions;  // passed to both sbatch calls, before the script
  bool dryRun = false;                     // write the scripts, submit nothing
  bool resume = false;                     // only the shards not finished in their folders
  EstimatorOptions estimator;              // passed on to every shard
  std::filesystem::path penumbra;          // the binary the jobs run
};

struct SlurmSubmission {
  std::size_t cases = 0;
  int shards = 0;
  std::vector<int> array;      // the shards submitted (empty: all were finished)
  std::string arrayJob;        // its job id ("" when none, or a dry run)
  std::string mergeJob;        // likewise
  std::string cancelledMerge;  // the previous merge job, cancelled (it waited on failed shards)
  std::vector<std::vector<std::string>> commands;  // the sbatch commands, as run or (dry) not
  std::filesystem::path shardScript, mergeScript;
};

// Throws SceneError (invalid study), std::invalid_argument (options; --resume without a
// submission, or of another study or shard count; jobs of the last submission still queued) and
// std::runtime_error (sbatch missing or refusing, files).
SlurmSubmission submitToSlurm(const Study& study, const SlurmSettings& settings);

}  // namespace penumbra
