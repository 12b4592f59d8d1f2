#include "cli/sweep_command.hpp"

#include <fmt/format.h>

#include <chrono>

#include "cli/exit_status.hpp"
#include "cli/sweep_progress.hpp"
#include "cli/version.hpp"
#include "output/staged_directory.hpp"
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

}  // namespace

int runSweepCommand(const SweepOptions& options) {
  return cli::reportingErrors([&] {
    SweepSettings settings;
    settings.output = options.output;
    if (!options.shard.empty()) settings.shard = parseShard(options.shard);
    settings.estimator = EstimatorOptions{options.device, options.reference, options.referenceN};
    settings.resume = options.resume;
    settings.version = kVersion;
    settings.charts = options.charts;
    settings.caseOutputs = options.caseOutputs;

    const auto start = std::chrono::steady_clock::now();
    const Study study = loadStudy(options.study);
    SweepProgress progress(!options.quiet);
    const SweepSummary summary = runSweep(study, settings, progress);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.quiet) return 0;
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
    return 0;
  });
}

int runMergeCommand(const MergeOptions& options) {
  return cli::reportingErrors([&] {
    const TableSummary table = mergeSweeps(options.inputs, options.output, options.charts);
    if (!options.quiet) printTable(table, options.output);
    return 0;
  });
}

}  // namespace penumbra
