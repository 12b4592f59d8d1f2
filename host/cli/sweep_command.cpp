#include "cli/sweep_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/exit_status.hpp"
#include "cli/sweep_progress.hpp"
#include "cli/version.hpp"
#include "cluster/process.hpp"
#include "cluster/slurm_scripts.hpp"
#include "cluster/slurm_submission.hpp"
#include "output/staged_directory.hpp"
#include "study/case_renders.hpp"
#include "study/study_reader.hpp"
#include "study/sweep_runner.hpp"

namespace penumbra {
namespace {

// What is in OUT now: the table, the cases still missing, the charts.
void printTable(const TableSummary& table, const std::filesystem::path& output) {
  const std::string out = normalizedTarget(output).string();
  fmt::print("results in {}: results.csv and design-explorer.csv ({} case{}), cases/\n", out,
             table.rows, table.rows == 1 ? "" : "s");
  if (!table.missing.empty()) {
    fmt::print(
        "not finished in this folder yet: {} case{} ({}{}); rerun, or join shard folders "
        "with `penumbra merge`\n",
        table.missing.size(), table.missing.size() == 1 ? "" : "s", table.missing.front(),
        table.missing.size() > 1 ? " … " + table.missing.back() : "");
  }
  if (table.charts > 0) {
    fmt::print("charts: {} in {}/charts\n", table.charts, out);
  } else {
    fmt::print("charts: none ({})\n", table.chartsNote);
  }
}

// Charts that could not be drawn: a clear error naming them (the results are there) and exit
// status 1; 0 when every chart is there.
int reportMissingCharts(const TableSummary& table, const std::filesystem::path& output,
                        const std::string& rerun) {
  if (table.chartsMissing.empty()) return 0;
  std::string names;
  for (const std::string& name : table.chartsMissing) names += (names.empty() ? "" : ", ") + name;
  fmt::print(stderr,
             "penumbra: error: {} chart{} not drawn in {}/charts ({}): {}\n"
             "  the results are written (results.csv, cases/); {} draws only the missing "
             "charts\n",
             table.chartsMissing.size(), table.chartsMissing.size() == 1 ? "" : "s",
             normalizedTarget(output).string(), names, table.chartsError, rerun);
  return 1;
}

// Case pictures that could not be drawn: named, with the error (the cases' results are there),
// and exit status 1.
int reportMissingPictures(const SweepSummary& summary, const std::filesystem::path& output) {
  if (summary.picturesMissing.empty()) return 0;
  std::string names;
  for (const std::string& name : summary.picturesMissing) {
    names += (names.empty() ? "" : ", ") + name;
  }
  fmt::print(stderr,
             "penumbra: error: {} case picture{} not drawn in {} ({}): {}\n"
             "  the cases' results are written; the same command run again draws only the "
             "missing pictures\n",
             summary.picturesMissing.size(), summary.picturesMissing.size() == 1 ? "" : "s",
             normalizedTarget(output).string(), names, summary.picturesError);
  return 1;
}

std::string commandLine(const std::vector<std::string>& words) {
  std::string text;
  for (const std::string& w : words) {
    const bool plain = w.find_first_of(" '\"$*?;&|<>()") == std::string::npos;
    text += (text.empty() ? "" : " ") + (plain ? w : shellQuote(w));
  }
  return text;
}

// --slurm: the shards go to Slurm; this process computes nothing.
int submitSweep(const SweepOptions& options) {
  if (!options.shard.empty()) {
    throw std::invalid_argument("--shard and --slurm: give --shards N, Slurm runs every shard");
  }
  if (options.shards == 0 && !options.resume) {
    throw std::invalid_argument("--slurm needs --shards N (the number of array tasks)");
  }
  SlurmSettings settings;
  settings.output = options.output;
  settings.shards = options.shards;
  for (const std::string& text : options.slurmOptions) {
    for (std::string& word : splitShellWords(text)) settings.sbatchOptions.push_back(word);
  }
  settings.dryRun = options.dryRun;
  settings.resume = options.resume;
  settings.estimator = options.estimator;
  settings.penumbra = std::filesystem::read_symlink("/proc/self/exe");
  const SlurmSubmission s = submitToSlurm(loadStudy(options.study), settings);
  if (options.quiet && !options.dryRun) return 0;
  const std::string out = normalizedTarget(options.output).string();
  fmt::print("{}: {} cases in {} shards", options.study.string(), s.cases, s.shards);
  if (options.resume) {
    fmt::print("; shards to run again: {}", s.array.empty() ? "none" : arraySpec(s.array));
  }
  fmt::print("\n");
  if (!s.cancelledMerge.empty()) {
    fmt::print("cancelled the merge job {} of the last submission\n", s.cancelledMerge);
  }
  if (options.dryRun) {
    fmt::print("dry run: scripts in {}/slurm; to submit them:\n", out);
    for (const auto& command : s.commands) fmt::print("  {}\n", commandLine(command));
    return 0;
  }
  if (!s.arrayJob.empty()) {
    fmt::print("shards {}: job array {} ({})\n", arraySpec(s.array), s.arrayJob,
               s.shardScript.string());
  }
  fmt::print("merge: job {}{} ({})\n", s.mergeJob,
             s.arrayJob.empty() ? "" : ", after every shard succeeded", s.mergeScript.string());
  fmt::print("results: {}/results.csv when job {} is done; logs in {}/slurm/logs\n", out,
             s.mergeJob, out);
  return 0;
}

}  // namespace

int runSweepCommand(const SweepOptions& options) {
  return cli::reportingErrors([&] {
    if (options.slurm) return submitSweep(options);
    SweepSettings settings;
    settings.output = options.output;
    if (!options.shard.empty()) settings.shard = parseShard(options.shard);
    settings.estimator = options.estimator;
    settings.resume = options.resume;
    settings.version = kVersion;
    settings.charts = options.charts;
    settings.caseOutputs = options.caseOutputs;

    const auto start = std::chrono::steady_clock::now();
    Study study = loadStudy(options.study);
    study.renderExposure = options.exposure;
    study.renderDisplay = renderDisplayName(options.renderDisplay);
    if (!options.exposure.empty() && study.renders.empty()) {
      throw std::invalid_argument("--exposure: the study renders nothing (it has no `renders:`)");
    }
    if (!study.renderDisplay.empty() && study.renders.empty()) {
      throw std::invalid_argument(
          "--display-luminance, --ambient: the study renders nothing (it has no `renders:`)");
    }
    // Renders need no display: host/ writes them, on the device the grids use.
    if (!study.renders.empty() && !options.estimator.reference) {
      settings.caseOutputs.push_back(std::make_shared<CaseRenders>(study.renders, options.estimator,
                                                                   options.exposure, options.output,
                                                                   options.renderDisplay));
    }
    SweepProgress progress(!options.quiet);
    const SweepSummary summary = runSweep(study, settings, progress);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto failures = [&] {
      const int pictures = reportMissingPictures(summary, options.output);
      const int charts =
          reportMissingCharts(summary.table, options.output, "the same command run again");
      return std::max(pictures, charts);
    };
    if (options.quiet) return failures();
    std::string shard;
    if (settings.shard.count > 1) {
      shard = fmt::format(" (shard {}/{})", settings.shard.index, settings.shard.count);
    }
    fmt::print("{}: {} cases{}; computed {}{}, already finished {} in {:.1f} s{}\n",
               options.study.string(), summary.cases, shard, summary.computed,
               summary.recomputed > 0
                   ? fmt::format(" ({} because their inputs changed)", summary.recomputed)
                   : "",
               summary.skipped, seconds, summary.device.empty() ? "" : " · on " + summary.device);
    for (const std::string& note : summary.outputNotes) fmt::print("{}\n", note);
    printTable(summary.table, options.output);
    return failures();
  });
}

int runMergeCommand(const MergeOptions& options) {
  return cli::reportingErrors([&] {
    const TableSummary table = mergeSweeps(options.inputs, options.output, options.charts);
    if (!options.quiet) printTable(table, options.output);
    return reportMissingCharts(table, options.output, "`penumbra merge` run again");
  });
}

}  // namespace penumbra
