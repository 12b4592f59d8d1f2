#pragma once
// Runs a study (docs/sweeps.md): one device and one compiled program for every case, each case
// into its own folder, finished cases skipped, then the tables and charts of every finished case.
// `penumbra merge` joins the folders of shards into one.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "illuminance/estimator.hpp"
#include "output/case_output.hpp"
#include "output/sweep_files.hpp"
#include "study/study.hpp"
#include "study/study_cases.hpp"
#include "study/study_layout.hpp"

namespace penumbra {

// Told how a sweep goes (the progress bar); every method does nothing by default.
class SweepObserver {
 public:
  virtual ~SweepObserver() = default;
  // Before the first case: how many this run computes, how many of its shard are done already.
  virtual void planned(std::size_t /*toCompute*/, std::size_t /*finished*/) {}
  virtual void caseStarted(const PlannedCase& /*c*/) {}
  virtual void caseFinished(const CaseRecord& /*record*/, double /*seconds*/) {}
};

struct SweepSettings {
  std::filesystem::path output;
  Shard shard;
  EstimatorOptions estimator;
  bool resume = false;  // OUT must hold a run of this very study
  std::string version;  // penumbra's, for each case's summary.json
  ChartWriter charts;   // empty: no charts (a build without viz/)
  // The per-case output writers this binary has (case_output.hpp); a study uses those it asks for
  // by name. Shared: the command line builds them, the runner only calls them.
  std::vector<std::shared_ptr<CaseOutputWriter>> caseOutputs;
};

// What ended up in OUT, for the closing message.
struct TableSummary {
  std::size_t rows = 0;              // finished cases in results.csv
  std::vector<std::string> missing;  // cases not finished in OUT (other shards', or killed)
  std::size_t charts = 0;            // charts in OUT/charts, drawn now or kept
  std::string chartsNote;            // why there are none, when there are none
  // Charts that could not be drawn (the tables are written all the same) and why: the command
  // then fails, and a rerun draws only these.
  std::vector<std::string> chartsMissing;
  std::string chartsError;
};

struct SweepSummary {
  std::size_t cases = 0;       // in the study
  std::size_t computed = 0;    // by this run
  std::size_t skipped = 0;     // of this shard, finished before this run
  std::size_t recomputed = 0;  // of `computed`, cases whose old folder was stale
  std::string device;          // empty when nothing was computed
  // Per-case outputs asked for but not written, each "<name>: none (<why>)".
  std::vector<std::string> outputNotes;
  // Case pictures that could not be drawn ("cases/case-002/work-plane.png"; the cases' results
  // are written all the same) and the first error: the command then fails, and a rerun draws
  // only these.
  std::vector<std::string> picturesMissing;
  std::string picturesError;
  TableSummary table;
};

// Throws SceneError (invalid study or case scene: nothing is written), std::invalid_argument
// (--resume into a folder without this study) or std::runtime_error (device, files).
SweepSummary runSweep(const Study& study, const SweepSettings& settings, SweepObserver& observer);

// Joins the case folders of `inputs` (shards of one sweep) into `output` and writes its tables
// and charts. Throws std::invalid_argument when an input is no sweep folder or they hold
// different studies.
TableSummary mergeSweeps(const std::vector<std::filesystem::path>& inputs,
                         const std::filesystem::path& output, const ChartWriter& charts);

}  // namespace penumbra
