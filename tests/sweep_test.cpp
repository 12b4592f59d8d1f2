// The sweep runner in-process: what reruns skip and recompute, --resume, and the chart and plot
// hooks that a binary with viz/ sets (fakes here, so that host/ is tested without VTK).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene_loader.hpp"
#include "study/study_reader.hpp"
#include "study/sweep_runner.hpp"
#include "sweep_scenes.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

using testing::readText;
using testing::TempDir;

using testing::kParameterisedRoom;

constexpr const char* kStudy = R"(penumbra-study: 1
scene: scene.yaml
parameters:
  flux: [1000, 2000]
  y: [1, 2, 3]
)";

void write(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

class SweepRunner : public ::testing::Test {
 protected:
  SweepRunner() : dir_("penumbra-sweep-runner") {
    write(dir_.path() / "scene.yaml", kParameterisedRoom);
    write(dir_.path() / "study.yaml", kStudy);
    settings_.output = dir_.path() / "out";
    settings_.estimator.device = "cpu";
    settings_.version = "test";
  }
  SweepSummary run() {
    SweepObserver silent;
    return runSweep(loadStudy(dir_.path() / "study.yaml"), settings_, silent);
  }
  fs::path out(const std::string& name = "") const { return dir_.path() / "out" / name; }

  TempDir dir_;
  SweepSettings settings_;
};

TEST_F(SweepRunner, RerunsSkipFinishedCasesAndRecomputeChangedOnes) {
  SweepSummary first = run();
  EXPECT_EQ(first.cases, 6u);
  EXPECT_EQ(first.computed, 6u);
  EXPECT_EQ(first.table.rows, 6u);
  EXPECT_TRUE(first.table.missing.empty());
  const std::string table = readText(out("results.csv"));

  SweepSummary again = run();
  EXPECT_EQ(again.computed, 0u);
  EXPECT_EQ(again.skipped, 6u);
  EXPECT_TRUE(again.device.empty());  // no device opened when nothing is left to compute
  EXPECT_EQ(readText(out("results.csv")), table);

  // The scene changes under the study (a comment does not count, the panel's size does).
  write(dir_.path() / "scene.yaml", std::string("# the same room\n") + kParameterisedRoom);
  EXPECT_EQ(run().computed, 0u);
  std::string bigger = kParameterisedRoom;
  bigger.replace(bigger.find("size: [0.5, 0.5]"), 16, "size: [0.6, 0.6]");
  write(dir_.path() / "scene.yaml", bigger);
  const SweepSummary changed = run();
  EXPECT_EQ(changed.computed, 6u);
  EXPECT_EQ(changed.recomputed, 6u);
  EXPECT_NE(readText(out("results.csv")), table);
}

// A scene with observers gets UGR_max per case. UGR grows as 8 log₁₀ of the flux (L² ∝ Φ², the
// interreflected L_b ∝ Φ), so doubling the panel's flux adds 8 log₁₀ 2; a scene without observers
// has no such column (the other tests' tables).
TEST_F(SweepRunner, ScenesWithObserversGetUgrMax) {
  std::string scene = kParameterisedRoom;
  scene.replace(scene.find("room: {size: [3, \"${y + 1}\", 3]}"), 32,
                "materials: {paint: 0.6}\nroom: {size: [3, \"${y + 1}\", 3], materials: {floor: "
                "paint, ceiling: paint, walls: paint}}");
  write(dir_.path() / "scene.yaml",
        scene + "observers:\n  - {name: desk, eye: [1.5, 0.1, 1.6], look: [0, 1, 0]}\n");
  write(dir_.path() / "study.yaml",
        "penumbra-study: 1\nscene: scene.yaml\nparameters:\n  flux: [1000, 2000]\n  y: [2]\n");
  const SweepSummary summary = run();
  ASSERT_EQ(summary.table.rows, 2u);
  std::ifstream in(out("results.csv"));
  std::string header, first, second;
  std::getline(in, header);
  std::getline(in, first);
  std::getline(in, second);
  EXPECT_EQ(header.substr(header.rfind(',') + 1), "UGR_max");
  const double ugr1000 = std::stod(first.substr(first.rfind(',') + 1));
  const double ugr2000 = std::stod(second.substr(second.rfind(',') + 1));
  EXPECT_NEAR(ugr2000 - ugr1000, 8 * std::log10(2.0), 1e-4);
  EXPECT_GT(ugr1000, 0.0);
}

TEST_F(SweepRunner, ResumeNeedsARunOfTheSameStudy) {
  settings_.resume = true;
  EXPECT_THROW(run(), std::invalid_argument);
  EXPECT_FALSE(fs::exists(out()));
  settings_.resume = false;
  settings_.shard = Shard{1, 2};
  EXPECT_EQ(run().computed, 3u);
  settings_.resume = true;
  settings_.shard = Shard{};
  const SweepSummary resumed = run();
  EXPECT_EQ(resumed.computed, 3u);
  EXPECT_EQ(resumed.skipped, 3u);
  write(dir_.path() / "study.yaml", std::string(kStudy) + "metrics: [Eavg]\n");
  EXPECT_THROW(run(), std::invalid_argument);
}

// A per-case output as viz/'s plots are one: writes one file per case from the case's scene and
// results, and lists it as an image. `why` non-empty: it cannot work here.
class FakeOutput : public CaseOutputWriter {
 public:
  FakeOutput(std::string name, std::string file, std::string why = "")
      : name_(std::move(name)), file_(std::move(file)), why_(std::move(why)) {}
  std::string name() const override { return name_; }
  std::string unavailable() const override { return why_; }
  std::vector<std::string> write(const Scene& scene, const RunReport& report,
                                 const fs::path& folder) override {
    EXPECT_TRUE(fs::exists(folder / "summary.json"));  // the grid files come first
    EXPECT_EQ(folder.filename().string().rfind(".case-", 0), 0u) << folder;  // staged
    std::ofstream(folder / file_) << scene.parameters[1].value << report.grids.size();
    ++calls;
    return {file_};
  }
  int calls = 0;

 private:
  std::string name_, file_, why_;
};

TEST_F(SweepRunner, ChartsAndPlotsGoThroughTheHooks) {
  std::vector<LineChart> drawn;
  settings_.charts.draw = [&](const std::vector<ChartFile>& charts, const fs::path& directory) {
    for (const ChartFile& c : charts) {
      drawn.push_back(c.chart);
      std::ofstream(directory / c.fileName) << "png";
    }
  };
  const auto plots = std::make_shared<FakeOutput>("plots", "floor-plot.png");
  // A writer the study does not ask for (renders, one day) is not called.
  const auto renders = std::make_shared<FakeOutput>("renders", "view.exr");
  settings_.caseOutputs = {renders, plots};
  write(dir_.path() / "study.yaml", std::string(kStudy) + "plots: true\n");
  const SweepSummary summary = run();
  EXPECT_TRUE(summary.outputNotes.empty());
  EXPECT_EQ(plots->calls, 6);
  EXPECT_EQ(renders->calls, 0);
  EXPECT_EQ(summary.table.charts, 10u);  // 5 metrics × 2 varied parameters
  ASSERT_EQ(drawn.size(), 10u);
  EXPECT_EQ(drawn[0].title, "Eavg [lx] vs flux");
  EXPECT_EQ(drawn[0].series.size(), 3u);  // one per y
  EXPECT_TRUE(fs::exists(out("charts/Eavg_lx-vs-flux.png")));
  EXPECT_TRUE(fs::exists(out("charts/Ud-vs-y.png")));
  EXPECT_EQ(readText(out("cases/case-006/floor-plot.png")), "31");
  const auto rows = testing::lines(readText(out("results.csv")));
  EXPECT_TRUE(rows[0].ends_with(",floor-plot_png")) << rows[0];
  EXPECT_TRUE(rows[1].ends_with(",cases/case-001/floor-plot.png")) << rows[1];
  EXPECT_TRUE(
      testing::lines(readText(out("design-explorer.csv")))[0].ends_with(",img:floor-plot_png"));

  // Without the hooks (a binary without viz/) the same study says why there are none.
  settings_.charts = {};
  settings_.caseOutputs = {};
  fs::remove_all(out());
  const SweepSummary plain = run();
  EXPECT_EQ(plain.table.charts, 0u);
  EXPECT_NE(plain.table.chartsNote.find("without charts"), std::string::npos);
  ASSERT_EQ(plain.outputNotes.size(), 1u);
  EXPECT_NE(plain.outputNotes[0].find("plots: none (this penumbra cannot write them)"),
            std::string::npos)
      << plain.outputNotes[0];
}

// A chart writer that stops halfway (VTK aborting its child process) costs only the charts it did
// not draw: the tables are written, the missing charts named, and a rerun draws only those; charts
// whose data did not change are kept.
TEST_F(SweepRunner, ChartsNotDrawnAreNamedAndARerunDrawsOnlyThem) {
  std::vector<std::string> asked;
  settings_.charts.draw = [&](const std::vector<ChartFile>& charts, const fs::path& directory) {
    for (const ChartFile& c : charts) asked.push_back(c.fileName);
    std::ofstream(directory / charts.front().fileName) << "png";
    if (charts.size() > 1) throw std::runtime_error("killed by signal 6 (Aborted)");
  };
  const SweepSummary broken = run();
  EXPECT_EQ(broken.table.rows, 6u);
  EXPECT_TRUE(fs::exists(out("results.csv")));
  // 5 metrics × 2 varied parameters; a drawing that fails is tried once more for what it left,
  // so the 10 names are asked for, then the 9 the first try left.
  ASSERT_EQ(asked.size(), 19u);
  EXPECT_EQ(broken.table.charts, 2u);
  ASSERT_EQ(broken.table.chartsMissing.size(), 8u);
  EXPECT_EQ(broken.table.chartsMissing.front(), asked[2]);
  EXPECT_EQ(broken.table.chartsError, "killed by signal 6 (Aborted)");
  EXPECT_TRUE(fs::exists(out("charts") / asked[0]));
  EXPECT_TRUE(fs::exists(out("charts") / asked[1]));
  EXPECT_FALSE(fs::exists(out("charts") / asked[2]));

  // Each rerun computes nothing and draws two of the missing charts (this writer draws one per
  // call, and each run tries twice); the ones already drawn are not asked for again.
  std::vector<std::string> missing(asked.begin() + 2, asked.begin() + 10);
  std::vector<std::string> redrawn;
  for (std::size_t round = 1; round <= 4; ++round) {
    asked.clear();
    const SweepSummary rerun = run();
    EXPECT_EQ(rerun.computed, 0u);
    const std::size_t before = 10u - 2u * round;  // missing when this round starts
    ASSERT_EQ(asked.size(), 2u * before - 1u);
    redrawn.push_back(asked[0]);
    redrawn.push_back(asked[before]);
    EXPECT_EQ(rerun.table.charts, 2u + 2u * round);
    EXPECT_EQ(rerun.table.chartsMissing.size(), 8u - 2u * round);
  }
  EXPECT_EQ(redrawn, missing);
  asked.clear();
  const SweepSummary complete = run();
  EXPECT_TRUE(asked.empty());
  EXPECT_EQ(complete.table.charts, 10u);
  EXPECT_TRUE(complete.table.chartsMissing.empty());

  // New results (a bigger panel) change the charts' data: those charts are drawn again.
  std::string bigger = kParameterisedRoom;
  bigger.replace(bigger.find("size: [0.5, 0.5]"), 16, "size: [0.6, 0.6]");
  write(dir_.path() / "scene.yaml", bigger);
  settings_.charts.draw = [&](const std::vector<ChartFile>& charts, const fs::path& directory) {
    for (const ChartFile& c : charts) {
      asked.push_back(c.fileName);
      std::ofstream(directory / c.fileName) << "png";
    }
  };
  EXPECT_EQ(run().computed, 6u);
  EXPECT_NE(std::find(asked.begin(), asked.end(), "Eavg_lx-vs-flux.png"), asked.end());
}

// A writer that cannot work here (no display) is left out of the whole run, and the cases are
// recorded without it: a later run that can draw them computes every case again, with them.
TEST_F(SweepRunner, AnOutputThatCannotBeWrittenHereIsLeftOutAndDoneLater) {
  write(dir_.path() / "study.yaml", std::string(kStudy) + "plots: true\n");
  const auto blind = std::make_shared<FakeOutput>("plots", "floor-plot.png", "no display");
  settings_.caseOutputs = {blind};
  const SweepSummary without = run();
  EXPECT_EQ(without.computed, 6u);
  EXPECT_EQ(blind->calls, 0);
  EXPECT_EQ(without.outputNotes, std::vector<std::string>{"plots: none (no display)"});
  EXPECT_FALSE(fs::exists(out("cases/case-001/floor-plot.png")));

  const auto seeing = std::make_shared<FakeOutput>("plots", "floor-plot.png");
  settings_.caseOutputs = {seeing};
  const SweepSummary with = run();
  EXPECT_EQ(with.recomputed, 6u);
  EXPECT_EQ(seeing->calls, 6);
  EXPECT_TRUE(fs::exists(out("cases/case-001/floor-plot.png")));
  EXPECT_EQ(run().computed, 0u);  // and now they are finished with plots
}

// Two outputs listing the same image would share a column of results.csv: the case fails and
// nothing of its folder appears.
TEST_F(SweepRunner, TwoOutputsCannotListTheSameImage) {
  const Scene scene = parseScene(kParameterisedRoom, dir_.path() / "scene.yaml");
  RunReport report;
  FakeOutput plots("plots", "same.png"), renders("renders", "same.png");
  const fs::path folder = out("cases/case-001");
  EXPECT_THROW(writeCaseFolder(folder, scene, report, {}, {&plots, &renders}), std::runtime_error);
  EXPECT_FALSE(fs::exists(folder));
  EXPECT_TRUE(!fs::exists(out("cases")) || fs::is_empty(out("cases")));
  writeCaseFolder(folder, scene, report, {}, {&plots});
  EXPECT_EQ(readText(folder / "same.png"), "10");
}

TEST_F(SweepRunner, MergeRefusesFoldersThatAreNotSweeps) {
  fs::create_directories(dir_.path() / "empty");
  EXPECT_THROW(mergeSweeps({dir_.path() / "empty"}, dir_.path() / "joined", {}),
               std::invalid_argument);
  EXPECT_THROW(mergeSweeps({}, dir_.path() / "joined", {}), std::invalid_argument);
  run();
  // Merging one complete folder into itself only rebuilds its table.
  const std::string table = readText(out("results.csv"));
  fs::remove(out("results.csv"));
  EXPECT_EQ(mergeSweeps({out()}, out(), {}).rows, 6u);
  EXPECT_EQ(readText(out("results.csv")), table);
}

}  // namespace
}  // namespace penumbra
