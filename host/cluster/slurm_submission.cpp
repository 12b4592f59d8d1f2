#include "cluster/slurm_submission.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "cluster/process.hpp"
#include "cluster/slurm_scripts.hpp"
#include "output/staged_directory.hpp"
#include "output/sweep_files.hpp"
#include "study/study_cases.hpp"
#include "study/study_layout.hpp"
#include "study/study_plan.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// What OUT/slurm/submission.json records of the last submission.
struct Submitted {
  int shards = 0;
  std::string arrayJob, mergeJob;
};

std::optional<Submitted> readSubmitted(const fs::path& out) {
  const fs::path file = slurmFolder(out) / kSubmissionJson;
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    const nlohmann::json json = nlohmann::json::parse(in);
    return Submitted{json.at("shards").get<int>(), json.at("array_job").get<std::string>(),
                     json.at("merge_job").get<std::string>()};
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(
        fmt::format("{}: not a file penumbra wrote ({})", file.string(), e.what()));
  }
}

void writeSubmitted(const fs::path& out, const Submitted& s, const std::vector<int>& array) {
  const nlohmann::ordered_json json = {{"shards", s.shards},
                                       {"array", arraySpec(array)},
                                       {"array_job", s.arrayJob},
                                       {"merge_job", s.mergeJob}};
  writeTextFiles(slurmFolder(out), {{kSubmissionJson, json.dump(2) + "\n"}});
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) text += (text.empty() ? "" : " ") + w;
  return text;
}

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

// Runs sbatch --parsable and returns the job id it prints ("<id>" or "<id>;<cluster>").
std::string submit(const std::vector<std::string>& command) {
  const ProcessResult r = runProcess(command);
  const std::string id = trimmed(r.out.substr(0, r.out.find(';')));
  if (r.status != 0 || id.empty() ||
      !std::all_of(id.begin(), id.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    throw std::runtime_error(fmt::format("`{}` failed (exit status {}): {}", joined(command),
                                         r.status, trimmed(r.err + r.out)));
  }
  return id;
}

// The ids of this user's jobs Slurm still holds (pending, running, completing); array tasks are
// listed as <array>_<task> or <array>_[<tasks>].
std::vector<std::string> queuedJobs() {
  const ProcessResult r = runProcess({"squeue", "--me", "--noheader", "--format=%i"});
  if (r.status != 0) {
    throw std::runtime_error(
        fmt::format("`squeue --me` failed (exit status {}): {}", r.status, trimmed(r.err)));
  }
  std::vector<std::string> ids;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    if (!trimmed(line).empty()) ids.push_back(trimmed(line));
  }
  return ids;
}

bool isPartOf(const std::string& id, const std::string& job) {
  return !job.empty() && (id == job || id.starts_with(job + "_"));
}

// The last submission's jobs: its shards must be over before their folders are judged, and its
// merge, still waiting on shards that will not all succeed, gives way to the new one.
std::string settlePrevious(const Submitted& previous) {
  const std::vector<std::string> queued = queuedJobs();
  for (const std::string& id : queued) {
    if (isPartOf(id, previous.arrayJob)) {
      throw std::invalid_argument(fmt::format(
          "shards of the last submission (job array {}) are still queued or running: wait for "
          "them, or cancel them with `scancel {}`, then run this again",
          previous.arrayJob, previous.arrayJob));
    }
  }
  for (const std::string& id : queued) {
    if (isPartOf(id, previous.mergeJob)) {
      const ProcessResult r = runProcess({"scancel", previous.mergeJob});
      if (r.status != 0) {
        throw std::runtime_error(
            fmt::format("`scancel {}` failed: {}", previous.mergeJob, trimmed(r.err)));
      }
      return previous.mergeJob;
    }
  }
  return "";
}

// A shard is finished when its folder holds this very study and every case of the shard.
bool shardFinished(const StudyLayout& layout, const fs::path& out, int shard, int shards) {
  const fs::path folder = shardFolder(out, shard);
  const std::optional<StudyLayout> there = readLayout(folder);
  if (!there || !there->sameStudy(layout)) return false;
  const Shard which{shard, shards};
  for (std::size_t i = 0; i < layout.cases.size(); ++i) {
    if (which.contains(i) && !readFinishedCase(folder, layout.cases[i])) return false;
  }
  return true;
}

int shardCount(const SlurmSettings& settings, const std::optional<Submitted>& previous,
               std::size_t cases) {
  int shards = settings.shards;
  if (settings.resume) {
    if (!previous) {
      throw std::invalid_argument(fmt::format(
          "--resume: {} holds no Slurm submission (no slurm/{}); submit without --resume",
          settings.output.string(), kSubmissionJson));
    }
    if (shards != 0 && shards != previous->shards) {
      throw std::invalid_argument(
          fmt::format("--resume: the study was submitted in {} shards, not {}; resume with "
                      "--shards {} (or leave --shards out)",
                      previous->shards, shards, previous->shards));
    }
    shards = previous->shards;
  }
  if (shards < 1 || static_cast<std::size_t>(shards) > cases) {
    throw std::invalid_argument(fmt::format(
        "--shards {}: give 1 to {} (the study has {} case{}; a shard needs at least one)", shards,
        cases, cases, cases == 1 ? "" : "s"));
  }
  return shards;
}

}  // namespace

SlurmSubmission submitToSlurm(const Study& study, const SlurmSettings& settings) {
  // The plan the shards will run: validates every case before anything is written or submitted.
  const StudyPlan plan =
      planStudy(study, estimatorIdentity(settings.estimator), requestedCaseOutputs(study),
                settings.estimator.interreflection && !settings.estimator.reference);
  const fs::path out = normalizedTarget(settings.output);
  checkOutputTarget(out);
  const std::optional<Submitted> previous = readSubmitted(out);

  SlurmSubmission result;
  result.cases = plan.layout.cases.size();
  result.shards = shardCount(settings, previous, result.cases);
  if (previous && !settings.dryRun) result.cancelledMerge = settlePrevious(*previous);
  for (int shard = 1; shard <= result.shards; ++shard) {
    if (!settings.resume || !shardFinished(plan.layout, out, shard, result.shards)) {
      result.array.push_back(shard);
    }
  }

  SlurmJobs jobs;
  jobs.penumbra = fs::absolute(settings.penumbra);
  jobs.study = fs::absolute(study.file).lexically_normal();
  jobs.output = out;
  jobs.shards = result.shards;
  jobs.array = result.array;
  jobs.estimator = settings.estimator;
  jobs.display = !requestedCaseOutputs(study).empty();
  jobs.charts = study.charts;
  jobs.name = "penumbra-" + study.file.stem().string();
  std::vector<std::pair<std::string, std::string>> scripts{{kMergeScript, mergeScript(jobs)}};
  if (!jobs.array.empty()) scripts.emplace_back(kShardScript, shardScript(jobs));
  writeTextFiles(slurmFolder(out), scripts);
  fs::create_directories(slurmFolder(out) / kLogsFolder);  // sbatch does not create it
  result.shardScript = slurmFolder(out) / kShardScript;
  result.mergeScript = slurmFolder(out) / kMergeScript;

  std::vector<std::string> arrayCommand{"sbatch", "--parsable"};
  arrayCommand.insert(arrayCommand.end(), settings.sbatchOptions.begin(),
                      settings.sbatchOptions.end());
  std::vector<std::string> mergeCommand = arrayCommand;
  arrayCommand.push_back(result.shardScript.string());
  // A shard that fails makes afterok impossible: Slurm then cancels the merge instead of keeping
  // it queued forever, and --resume submits a new one.
  mergeCommand.push_back("--kill-on-invalid-dep=yes");
  mergeCommand.push_back(result.mergeScript.string());
  if (!result.array.empty()) {
    result.commands.push_back(arrayCommand);
    const auto script = mergeCommand.end() - 1;
    mergeCommand.insert(script, "--dependency=afterok:" +
                                    (settings.dryRun ? std::string("<array job>") : "$ARRAY"));
  }
  result.commands.push_back(mergeCommand);
  if (settings.dryRun) return result;

  Submitted record{result.shards, "", ""};
  if (!result.array.empty()) {
    result.arrayJob = submit(arrayCommand);
    record.arrayJob = result.arrayJob;
    writeSubmitted(out, record, result.array);
    for (std::string& word : result.commands.back()) {
      if (word == "--dependency=afterok:$ARRAY") word = "--dependency=afterok:" + result.arrayJob;
    }
  }
  result.mergeJob = submit(result.commands.back());
  record.mergeJob = result.mergeJob;
  writeSubmitted(out, record, result.array);
  return result;
}

}  // namespace penumbra
