// `penumbra sweep --slurm` against a real Slurm: run by ctest under tests/slurm/with_slurm.sh,
// which starts a single-node cluster and sets SLURM_CONF. An 8-case study in 4 shards must merge
// into the very results.csv a local run writes; a shard cancelled with scancel, then --resume,
// must give that table too. Prints the wall times (local, through Slurm) for the record.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "../penumbra_process.hpp"
#include "../test_files.hpp"
#include "cluster/process.hpp"
#include "timing/seconds_since.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using testing::readText;
using testing::runPenumbra;
using testing::TempDir;

// 8 cases: the example office's window from 1.0 to 2.4 m, daylight only.
void writeStudy(const fs::path& dir) {
  std::ofstream(dir / "study.yaml")
      << "penumbra-study: 1\n"
      << "scene: " << PENUMBRA_SOURCE_DIR << "/data/office.yaml\n"
      << "parameters:\n  window_width_m: {range: {from: 1.0, to: 2.4, step: 0.2}}\n"
      << "  panel_flux_lm: [0]\n"
      << "grids: [work-plane]\n"
      // No charts: this test is about shards and the merged table, and needs no X server (two
      // merge jobs under xvfb-run once lost their display while the rest of the suite ran
      // beside them; the charts are tested by the sweep and viz tests).
      << "charts: false\n";
}

std::vector<std::string> queued() {
  const ProcessResult r = runProcess({"squeue", "--me", "--noheader", "--format=%i"});
  EXPECT_EQ(r.status, 0) << r.err;
  return testing::lines(r.out);
}

// Waits until Slurm holds no job that `belongs` accepts; false after `seconds`.
template <typename Belongs>
bool waitWhileQueued(Belongs belongs, double seconds = 240.0) {
  const auto start = Clock::now();
  while (secondsSince(start) < seconds) {
    bool any = false;
    for (const std::string& id : queued()) any = any || belongs(id);
    if (!any) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  return false;
}

bool anyJob(const std::string&) {
  return true;
}

// The job ids printed by `penumbra sweep --slurm`: "job array <id>" and "merge: job <id>".
std::string jobAfter(const std::string& out, const std::string& words) {
  const auto at = out.find(words);
  if (at == std::string::npos) return "";
  const auto start = at + words.size();
  return out.substr(start, out.find_first_not_of("0123456789", start) - start);
}

std::string jobState(const std::string& id) {
  const std::string show = runProcess({"scontrol", "show", "job", id}).out;
  const auto at = show.find("JobState=");
  return at == std::string::npos ? "unknown" : show.substr(at + 9, show.find(' ', at) - at - 9);
}

std::string logsOf(const fs::path& out) {
  std::string text;
  const fs::path logs = out / "slurm" / "logs";
  if (!fs::is_directory(logs)) return "(no logs)";
  for (const auto& entry : fs::directory_iterator(logs)) {
    text += "--- " + entry.path().filename().string() + "\n" + readText(entry.path());
  }
  return text;
}

class SlurmSweep : public ::testing::Test {
 protected:
  void SetUp() override {
    // Never a silent pass: this test exists to run against Slurm.
    ASSERT_NE(std::getenv("SLURM_CONF"), nullptr)
        << "SLURM_CONF is not set: run this test through tests/slurm/with_slurm.sh (ctest does)";
    writeStudy(dir_.path());
    const auto start = Clock::now();
    const testing::Result local = runPenumbra(dir_.path(), "sweep study.yaml -o local -q");
    ASSERT_EQ(local.status, 0) << local.err;
    std::cout << "[ timing ] local sweep of 8 cases: " << secondsSince(start) << " s\n";
    localTable_ = readText(dir_.path() / "local" / "results.csv");
    ASSERT_EQ(testing::lines(localTable_).size(), 9u);  // header + 8 cases
  }

  TempDir dir_{"penumbra-slurm"};
  std::string localTable_;
};

TEST_F(SlurmSweep, FourShardsMergeIntoTheTableOfALocalRun) {
  const auto start = Clock::now();
  const testing::Result submitted =
      runPenumbra(dir_.path(), "sweep study.yaml -o cluster --slurm --shards 4");
  const double submitSeconds = secondsSince(start);
  ASSERT_EQ(submitted.status, 0) << submitted.err << submitted.out;
  const std::string array = jobAfter(submitted.out, "job array ");
  const std::string merge = jobAfter(submitted.out, "merge: job ");
  ASSERT_FALSE(array.empty()) << submitted.out;
  ASSERT_FALSE(merge.empty()) << submitted.out;

  ASSERT_TRUE(waitWhileQueued(anyJob)) << logsOf(dir_.path() / "cluster");
  const double allSeconds = secondsSince(start);
  EXPECT_EQ(jobState(merge), "COMPLETED") << logsOf(dir_.path() / "cluster");
  EXPECT_EQ(readText(dir_.path() / "cluster" / "results.csv"), localTable_)
      << logsOf(dir_.path() / "cluster");
  for (int shard = 1; shard <= 4; ++shard) {
    EXPECT_TRUE(fs::exists(dir_.path() / "cluster" / "slurm" / "logs" /
                           ("shard-" + std::to_string(shard) + ".log")));
  }
  std::cout << "[ timing ] through Slurm, 4 shards: submission " << submitSeconds
            << " s, submission to merged results.csv " << allSeconds << " s\n";
}

TEST_F(SlurmSweep, ACancelledShardIsResubmittedAloneByResume) {
  // Held at submission, so that shard 2 is surely cancelled before it starts.
  const testing::Result submitted =
      runPenumbra(dir_.path(), "sweep study.yaml -o cluster --slurm --shards 4 --slurm-opt=--hold");
  ASSERT_EQ(submitted.status, 0) << submitted.err << submitted.out;
  const std::string array = jobAfter(submitted.out, "job array ");
  ASSERT_FALSE(array.empty()) << submitted.out;
  ASSERT_EQ(runProcess({"scancel", array + "_2"}).status, 0);
  ASSERT_EQ(runProcess({"scontrol", "release", array}).status, 0);
  ASSERT_TRUE(waitWhileQueued([&](const std::string& id) { return id.starts_with(array + "_"); }))
      << logsOf(dir_.path() / "cluster");

  // Shards 1, 3 and 4 finished their cases; shard 2 has none, and the merge never ran.
  const fs::path slurm = dir_.path() / "cluster" / "slurm";
  EXPECT_TRUE(fs::exists(slurm / "shard-1" / "cases" / "case-001" / "case.json"));
  EXPECT_FALSE(fs::exists(slurm / "shard-2" / "cases" / "case-002" / "case.json"));
  EXPECT_FALSE(fs::exists(dir_.path() / "cluster" / "results.csv"));

  const testing::Result resumed =
      runPenumbra(dir_.path(), "sweep study.yaml -o cluster --slurm --resume");
  ASSERT_EQ(resumed.status, 0) << resumed.err << resumed.out;
  EXPECT_NE(resumed.out.find("8 cases in 4 shards; shards to run again: 2\n"), std::string::npos)
      << resumed.out;
  EXPECT_NE(readText(slurm / "sweep.sbatch").find("#SBATCH --array=2\n"), std::string::npos);
  const std::string merge = jobAfter(resumed.out, "merge: job ");
  ASSERT_FALSE(merge.empty()) << resumed.out;
  ASSERT_TRUE(waitWhileQueued(anyJob)) << logsOf(dir_.path() / "cluster");
  EXPECT_EQ(jobState(merge), "COMPLETED") << logsOf(dir_.path() / "cluster");
  EXPECT_EQ(readText(dir_.path() / "cluster" / "results.csv"), localTable_)
      << logsOf(dir_.path() / "cluster");

  // Everything finished: a further --resume submits no shard, only the merge.
  const testing::Result again =
      runPenumbra(dir_.path(), "sweep study.yaml -o cluster --slurm --resume --shards 4");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_NE(again.out.find("shards to run again: none"), std::string::npos) << again.out;
  EXPECT_EQ(jobAfter(again.out, "job array "), "");
  ASSERT_TRUE(waitWhileQueued(anyJob));
  EXPECT_EQ(readText(dir_.path() / "cluster" / "results.csv"), localTable_);
}

}  // namespace
}  // namespace penumbra
