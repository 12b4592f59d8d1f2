#include "cluster/slurm_scripts.hpp"

#include <fmt/format.h>

#include "cluster/process.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// What both scripts start with. Charts and plots render through X (VTK); a compute node has no
// display, and one inherited from the submitting shell is not valid there: use a virtual one
// where xvfb-run is installed. `-n`: each job tries a server number of its own first, far from
// where `xvfb-run -a` starts (99): two of them starting at once on one node can otherwise pick
// the same number, and the loser then talks to the winner's server and VTK aborts. `-noreset`:
// the server would otherwise reset when its last client leaves, and a chart's window opened
// during the reset gets no connection (VTK aborts likewise).
std::string preamble(const std::string& directives, bool display) {
  std::string text = "#!/bin/bash\n" + directives +
                     "# Written by `penumbra sweep --slurm` (docs/cluster.md).\n"
                     "set -euo pipefail\n"
                     "# PoCL: as many threads as the cores Slurm gave the task.\n"
                     "if [[ -n \"${SLURM_CPUS_PER_TASK:-}\" ]]; then\n"
                     "  export POCL_MAX_PTHREAD_COUNT=\"${SLURM_CPUS_PER_TASK}\"\n"
                     "fi\n"
                     "run=()\n";
  if (display) {
    text +=
        "if command -v xvfb-run >/dev/null; then\n"
        "  run=(xvfb-run -a -n \"$((1000 + ${SLURM_JOB_ID:-$$} % 30000))\" -s \"-screen 0 "
        "1920x1080x24 -noreset\")\n"
        "fi\n";
  }
  return text;
}

std::string estimatorArguments(const EstimatorOptions& estimator) {
  std::string text = " --device " + shellQuote(estimator.device);
  if (estimator.reference)
    text += fmt::format(" --reference --reference-n {}", estimator.referenceN);
  if (!estimator.interreflection) text += " --direct-only";
  text += fmt::format(" --element-size {} --link-error {}", estimator.mesh.elementSize,
                      estimator.mesh.linkError);
  return text;
}

}  // namespace

fs::path slurmFolder(const fs::path& output) {
  return output / "slurm";
}

fs::path shardFolder(const fs::path& output, int shard) {
  return slurmFolder(output) / fmt::format("shard-{}", shard);
}

std::string arraySpec(const std::vector<int>& shards) {
  std::string text;
  for (std::size_t i = 0; i < shards.size();) {
    std::size_t j = i;
    while (j + 1 < shards.size() && shards[j + 1] == shards[j] + 1) ++j;
    if (!text.empty()) text += ',';
    text += j > i ? fmt::format("{}-{}", shards[i], shards[j]) : fmt::format("{}", shards[i]);
    i = j + 1;
  }
  return text;
}

std::string shardScript(const SlurmJobs& jobs) {
  const fs::path logs = slurmFolder(jobs.output) / kLogsFolder;
  const std::string directives =
      fmt::format("#SBATCH --job-name={}\n#SBATCH --array={}\n#SBATCH --output={}\n", jobs.name,
                  arraySpec(jobs.array), (logs / "shard-%a.log").string());
  // The array index is the shard number (1..N), as --shard counts.
  return preamble(directives, jobs.display) +
         fmt::format(
             "shard=\"${{SLURM_ARRAY_TASK_ID}}\"\n"
             "\"${{run[@]}}\" {} sweep {} -o {}\"/shard-${{shard}}\" --shard \"${{shard}}/{}\"{}\n",
             shellQuote(jobs.penumbra.string()), shellQuote(jobs.study.string()),
             shellQuote(slurmFolder(jobs.output).string()), jobs.shards,
             estimatorArguments(jobs.estimator));
}

std::string mergeScript(const SlurmJobs& jobs) {
  const fs::path logs = slurmFolder(jobs.output) / kLogsFolder;
  const std::string directives = fmt::format("#SBATCH --job-name={}-merge\n#SBATCH --output={}\n",
                                             jobs.name, (logs / "merge.log").string());
  std::string folders;
  for (int shard = 1; shard <= jobs.shards; ++shard) {
    folders += ' ';
    folders += shellQuote(shardFolder(jobs.output, shard).string());
  }
  return preamble(directives, jobs.charts) + fmt::format("\"${{run[@]}}\" {} merge{} -o {}\n",
                                                         shellQuote(jobs.penumbra.string()),
                                                         folders, shellQuote(jobs.output.string()));
}

}  // namespace penumbra
