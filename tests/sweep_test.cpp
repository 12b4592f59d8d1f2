// The sweep runner in-process: what reruns skip and recompute, --resume, and the chart and plot
// hooks that a binary with viz/ sets (fakes here, so that host/ is tested without VTK).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "scene/scene_loader.hpp"
#include "study/study_reader.hpp"
#include "study/sweep_runner.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

using testing::readText;
using testing::TempDir;

constexpr const char* kScene = R"(penumbra: 1
parameters: {flux: 1000, y: 1}
room: {size: [3, "${y + 1}", 3]}
sources:
  - {name: panel, rect: {center: [1.5, 1, 2.99], size: [0.5, 0.5], normal: [0, 0, -1]}, flux: "${flux}"}
grids:
  - {name: floor, height: 0, spacing: 0.5, margin: 0.25}
)";

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
    write(dir_.path() / "scene.yaml", kScene);
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
  write(dir_.path() / "scene.yaml", std::string("# the same room\n") + kScene);
  EXPECT_EQ(run().computed, 0u);
  std::string bigger = kScene;
  bigger.replace(bigger.find("size: [0.5, 0.5]"), 16, "size: [0.6, 0.6]");
  write(dir_.path() / "scene.yaml", bigger);
  const SweepSummary changed = run();
  EXPECT_EQ(changed.computed, 6u);
  EXPECT_EQ(changed.recomputed, 6u);
  EXPECT_NE(readText(out("results.csv")), table);
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

TEST_F(SweepRunner, ChartsAndPlotsGoThroughTheHooks) {
  std::vector<LineChart> drawn;
  settings_.charts = [&](const LineChart& chart, const fs::path& png) {
    drawn.push_back(chart);
    std::ofstream(png) << "png";
  };
  settings_.plots = [](const Scene& scene, const RunReport& report, const fs::path& folder) {
    EXPECT_TRUE(fs::exists(folder / "summary.json"));  // the grid files come first
    std::ofstream(folder / "floor-plot.png") << scene.parameters[1].value << report.grids.size();
    return std::vector<std::string>{"floor-plot.png"};
  };
  write(dir_.path() / "study.yaml", std::string(kStudy) + "plots: true\n");
  const SweepSummary summary = run();
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
  settings_.plots = {};
  fs::remove_all(out());
  const SweepSummary plain = run();
  EXPECT_EQ(plain.table.charts, 0u);
  EXPECT_NE(plain.table.chartsNote.find("without charts"), std::string::npos);
  EXPECT_NE(plain.plotsNote.find("cannot draw them in a sweep yet"), std::string::npos);
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
