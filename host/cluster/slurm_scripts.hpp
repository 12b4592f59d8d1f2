#pragma once
// The batch scripts `penumbra sweep --slurm` writes into OUT/slurm/ (docs/cluster.md): a job
// array with one task per shard, and the merge that joins the shards' folders into OUT. Text
// only; submitting them is slurm_submission.hpp's job.
#include <filesystem>
#include <string>
#include <vector>

#include "illuminance/estimator.hpp"

namespace penumbra {

struct SlurmJobs {
  std::filesystem::path penumbra;  // the binary the tasks run, absolute
  std::filesystem::path study;     // absolute
  std::filesystem::path output;    // OUT, absolute
  int shards = 1;                  // N
  std::vector<int> array;          // the shards (1..N) this submission runs, ascending
  EstimatorOptions estimator;
  bool display = false;  // the cases draw plots: run them under xvfb-run where there is one
  bool charts = true;    // the merge draws charts: run it under xvfb-run where there is one
  std::string name;      // job name stem, e.g. "penumbra-window-width"
};

// OUT/slurm and what is in it.
std::filesystem::path slurmFolder(const std::filesystem::path& output);
std::filesystem::path shardFolder(const std::filesystem::path& output, int shard);  // shard-<i>
inline constexpr const char* kShardScript = "sweep.sbatch";
inline constexpr const char* kMergeScript = "merge.sbatch";
inline constexpr const char* kSubmissionJson = "submission.json";
inline constexpr const char* kLogsFolder = "logs";

// "1-4", or "2,5,7" for some shards: Slurm's --array syntax.
std::string arraySpec(const std::vector<int>& shards);

// The job array: task $SLURM_ARRAY_TASK_ID runs `penumbra sweep STUDY --shard ID/N` into its
// shard folder; logs in OUT/slurm/logs/shard-<ID>.log.
std::string shardScript(const SlurmJobs& jobs);
// The merge: `penumbra merge` of every shard folder into OUT (tables and charts); log in
// OUT/slurm/logs/merge.log.
std::string mergeScript(const SlurmJobs& jobs);

}  // namespace penumbra
