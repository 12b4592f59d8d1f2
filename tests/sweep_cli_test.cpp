// `penumbra sweep` and `penumbra merge` as a user runs them (docs/sweeps.md, "Nothing is lost").
// Every case equals `penumbra grid` run on it alone, exactly; a killed run finished by a rerun
// equals an uninterrupted one and leaves finished cases untouched; shards merged equal one run.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "penumbra_process.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;

using penumbra::testing::lines;
using penumbra::testing::PenumbraProcess;
using penumbra::testing::readText;
using penumbra::testing::Result;
using penumbra::testing::runPenumbra;
using penumbra::testing::TempDir;

// A 6 × 4 × 3 m room with three panels and three boxes; box `a` moves with x, the panels' flux
// follows flux. `spacing` sets the work: the kill test wants cases that take a while.
std::string scene(double spacing) {
  return fmt::format(R"(penumbra: 1
parameters: {{flux: 3000, x: 1.5}}
room: {{size: [6, 4, 3]}}
solids:
  - {{name: a, box: {{min: ["${{x}}", 1, 0], max: ["${{x + 0.5}}", 1.5, 1]}}}}
  - {{name: b, box: {{min: [3, 2, 0], max: [3.5, 2.5, 1.2]}}}}
  - {{name: c, box: {{min: [4, 1, 0.5], max: [4.6, 1.4, 0.9]}}}}
sources:
  - {{name: p1, rect: {{center: [1.5, 1, 2.99], size: [0.6, 0.6], normal: [0, 0, -1]}}, flux: "${{flux}}"}}
  - {{name: p2, rect: {{center: [4.5, 1, 2.99], size: [0.6, 0.6], normal: [0, 0, -1]}}, flux: "${{flux}}"}}
  - {{name: p3, rect: {{center: [1.5, 3, 2.99], size: [0.6, 0.6], normal: [0, 0, -1]}}, flux: "${{flux}}"}}
grids:
  - {{name: floor, rect: {{origin: [0, 0, 0], u: [6, 0, 0], v: [0, 4, 0]}}, spacing: {}}}
  - {{name: probes, points: [[1.7, 1.2, 1.0, 0, 0, 1], [2, 3, 0.8, 0, 0, 1]]}}
)",
                     spacing);
}

// 2 fluxes × 3 positions of box a: 6 cases.
constexpr const char* kStudy = R"(penumbra-study: 1
scene: scene.yaml
parameters:
  flux: [3000, 4000]
  x: [0.5, 1.5, 2.5]
combination: grid
)";

void write(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

std::vector<std::vector<std::string>> csvRows(const fs::path& file) {
  std::vector<std::vector<std::string>> rows;
  for (const std::string& line : lines(readText(file))) {
    rows.emplace_back(1);
    for (char c : line) {
      if (c == ',') {
        rows.back().emplace_back();
      } else {
        rows.back().back() += c;
      }
    }
  }
  return rows;
}

// Every file under `folder` and its modification time.
std::map<std::string, fs::file_time_type> modificationTimes(const fs::path& folder) {
  std::map<std::string, fs::file_time_type> times{{".", fs::last_write_time(folder)}};
  for (const auto& entry : fs::recursive_directory_iterator(folder)) {
    times[fs::relative(entry.path(), folder).string()] = entry.last_write_time();
  }
  return times;
}

TEST(SweepCli, EveryCaseEqualsAGridRunOnItAlone) {
  TempDir dir("penumbra-sweep-cli");
  write(dir.path() / "scene.yaml", scene(0.25));
  write(dir.path() / "study.yaml", kStudy);
  const Result sweep = runPenumbra(dir.path(), "sweep study.yaml -o out --device cpu");
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  EXPECT_NE(sweep.out.find("6 cases; computed 6, already finished 0"), std::string::npos)
      << sweep.out;

  const auto rows = csvRows(dir.path() / "out" / "results.csv");
  ASSERT_EQ(rows.size(), 7u);
  const std::vector<std::string> header{
      "case_id",        "flux",      "x",        "Eavg_lx@floor",  "Emin_lx@floor",
      "Emax_lx@floor",  "U0@floor",  "Ud@floor", "Eavg_lx@probes", "Emin_lx@probes",
      "Emax_lx@probes", "U0@probes", "Ud@probes"};
  EXPECT_EQ(rows[0], header);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& row = rows[i];
    SCOPED_TRACE(row[0]);
    const std::string alone = "alone-" + row[0];
    const Result grid = runPenumbra(dir.path(), "grid scene.yaml -o " + alone + " --device cpu -q" +
                                                    " --set flux=" + row[1] + " --set x=" + row[2]);
    ASSERT_EQ(grid.status, 0) << grid.err;
    const auto summary = nlohmann::json::parse(readText(dir.path() / alone / "summary.json"));
    std::size_t column = 3;
    for (const auto& g : summary["grids"]) {
      for (const char* metric : {"Eavg_lx", "Emin_lx", "Emax_lx", "U0", "Ud"}) {
        // Both in the shortest form that reads back to the same double: equal strings, equal
        // numbers; an undefined metric (a point list's U0) null there and empty here.
        const std::string text =
            g[metric].is_null() ? std::string() : fmt::format("{}", g[metric].get<double>());
        EXPECT_EQ(row[column], text) << header[column];
        ++column;
      }
    }
    // The case folder holds what the grid run wrote, to the byte.
    EXPECT_EQ(readText(dir.path() / "out" / "cases" / row[0] / "floor.csv"),
              readText(dir.path() / alone / "floor.csv"));
  }
}

// The window of the daylight tests' scene.yaml at 1 and 3 m.
constexpr const char* kWindowWidthStudy = R"(penumbra-study: 1
scene: scene.yaml
parameters:
  width: [1.0, 3.0]
charts: false
)";

// A scene with a sky: the daylight factor columns (and the EN 17037 level, the site giving
// E_v,d,med) per case, each equal to what `penumbra grid` writes in summary.json for the case run
// alone; a wider window gives a higher mean DF. Direct only, a coarse grid: cheap.
TEST(SweepCli, DaylightColumnsEqualTheGridRunsDaylightFactor) {
  TempDir dir("penumbra-sweep-cli");
  write(dir.path() / "scene.yaml", R"(penumbra: 1
parameters: {width: 1.0}
site: {latitude_deg: 51.5, longitude_deg: -0.1, median_diffuse_illuminance_lx: 10000}
sky: {model: cie-overcast, horizontal_illuminance_lx: 10000}
room:
  size: [4, 4, 3]
  openings:
    - {name: w, wall: y0, x: "${2 - width/2}", z: 0.9, width: "${width}", height: 1.5}
grids:
  - {name: reference-plane, height: 0.85, spacing: 0.5, margin: 0.5}
)");
  write(dir.path() / "study.yaml", kWindowWidthStudy);
  const Result sweep =
      runPenumbra(dir.path(), "sweep study.yaml -o out --device cpu --direct-only");
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  const auto rows = csvRows(dir.path() / "out" / "results.csv");
  ASSERT_EQ(rows.size(), 3u);
  const std::vector<std::string> header{"case_id",   "width",        "Eavg_lx",      "Emin_lx",
                                        "Emax_lx",   "U0",           "Ud",           "DFavg_pct",
                                        "DFmin_pct", "DFmedian_pct", "EN17037_level"};
  ASSERT_EQ(rows[0], header);
  const std::map<std::string, int> levels{{"none", 0}, {"minimum", 1}, {"medium", 2}, {"high", 3}};
  std::vector<double> means;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& row = rows[i];
    SCOPED_TRACE(row[0]);
    const std::string alone = "alone-" + row[0];
    const Result grid =
        runPenumbra(dir.path(), "grid scene.yaml -o " + alone +
                                    " --device cpu -q --direct-only --set width=" + row[1]);
    ASSERT_EQ(grid.status, 0) << grid.err;
    const auto summary = nlohmann::json::parse(readText(dir.path() / alone / "summary.json"));
    const auto& df = summary["grids"][0]["daylight_factor"];
    EXPECT_EQ(row[7], fmt::format("{}", df["DFavg_pct"].get<double>()));
    EXPECT_EQ(row[8], fmt::format("{}", df["DFmin_pct"].get<double>()));
    EXPECT_EQ(row[9], fmt::format("{}", df["DFmedian_pct"].get<double>()));
    EXPECT_EQ(row[10],
              fmt::format("{}", levels.at(df["en17037"]["level_reached"].get<std::string>())));
    means.push_back(std::stod(row[7]));
  }
  std::printf("  DFavg %.3f %% (1 m window), %.3f %% (3 m)\n", means[0], means[1]);
  EXPECT_GT(means[1], means[0]);
}

// With interreflection the daylight factor's mean comes with its components: SC + ERC + IRC =
// DFavg in every row (to the digits written), each equal to what `penumbra grid` writes in
// summary.json for the case run alone and to what case.json keeps for rebuilding the table.
// A grey room behind the window and a white slab outside in front of it, so that every component
// has light; 1 m elements: cheap.
TEST(SweepCli, WithInterreflectionTheDaylightComponentsAddUpAndEqualTheGridRuns) {
  TempDir dir("penumbra-sweep-cli");
  write(dir.path() / "scene.yaml", R"(penumbra: 1
parameters: {width: 1.0}
materials: {grey: 0.5, white: 0.8}
sky: {model: cie-overcast, horizontal_illuminance_lx: 10000}
room:
  size: [4, 4, 3]
  materials: {floor: grey, ceiling: grey, walls: grey}
  openings:
    - {name: w, wall: y0, x: "${2 - width/2}", z: 0.9, width: "${width}", height: 1.5}
solids:
  - {name: slab, box: {min: [-4, -6, 0], max: [8, -5, 6]}, material: white}
grids:
  - {name: reference-plane, height: 0.85, spacing: 0.5, margin: 0.5}
)");
  write(dir.path() / "study.yaml", kWindowWidthStudy);
  const std::string options = " --device cpu --element-size 1";
  const Result sweep = runPenumbra(dir.path(), "sweep study.yaml -o out" + options);
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  const auto rows = csvRows(dir.path() / "out" / "results.csv");
  ASSERT_EQ(rows.size(), 3u);
  const std::vector<std::string> header{
      "case_id",   "width",     "Eavg_lx",      "Emin_lx",   "Emax_lx",    "U0",        "Ud",
      "DFavg_pct", "DFmin_pct", "DFmedian_pct", "SCavg_pct", "ERCavg_pct", "IRCavg_pct"};
  ASSERT_EQ(rows[0], header);
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& row = rows[i];
    SCOPED_TRACE(row[0]);
    const double mean = std::stod(row[7]), sc = std::stod(row[10]), erc = std::stod(row[11]),
                 irc = std::stod(row[12]);
    EXPECT_GT(sc, 0.0);
    EXPECT_GT(erc, 0.0);
    EXPECT_GT(irc, 0.0);
    EXPECT_NEAR(sc + erc + irc, mean, 1e-12 * mean);
    const std::string alone = "alone-" + row[0];
    const Result grid = runPenumbra(
        dir.path(), "grid scene.yaml -o " + alone + options + " -q --set width=" + row[1]);
    ASSERT_EQ(grid.status, 0) << grid.err;
    const auto summary = nlohmann::json::parse(readText(dir.path() / alone / "summary.json"));
    const auto& df = summary["grids"][0]["daylight_factor"];
    const auto record =
        nlohmann::json::parse(readText(dir.path() / "out" / "cases" / row[0] / "case.json"));
    for (const auto& [column, key] :
         {std::pair{10, "SCavg_pct"}, {11, "ERCavg_pct"}, {12, "IRCavg_pct"}}) {
      EXPECT_EQ(row[column], fmt::format("{}", df[key].get<double>())) << key;
      EXPECT_EQ(record["grids"][0][key], df[key]) << key;
    }
  }
}

TEST(SweepCli, SunColumnsEqualTheGridRunsSunlight) {
  TempDir dir("penumbra-sweep-cli");
  // The window faces south at north_deg 0 and west at 90; at 10:30 the sun is south-east.
  write(dir.path() / "scene.yaml", R"(penumbra: 1
parameters: {north: 0.0, hour: 10.0}
site: {latitude_deg: 51.5, longitude_deg: -0.1, north_deg: "${north}"}
sky: {model: cie-overcast, horizontal_illuminance_lx: 10000}
sun: {date: 2026-03-21, hour: "${hour}", direct_normal_illuminance_lx: 60000}
room:
  size: [4, 4, 3]
  openings:
    - {name: w, wall: y0, x: 1.0, z: 0.9, width: 2.0, height: 1.5, transmittance: 0.7}
grids:
  - {name: floor, height: 0.05, spacing: 0.5, margin: 0.25}
)");
  write(dir.path() / "study.yaml", R"(penumbra-study: 1
scene: scene.yaml
parameters:
  north: [0, 90]
  hour: [10.5]
charts: false
)");
  const Result sweep =
      runPenumbra(dir.path(), "sweep study.yaml -o out --device cpu --direct-only");
  ASSERT_EQ(sweep.status, 0) << sweep.err;
  const auto rows = csvRows(dir.path() / "out" / "results.csv");
  ASSERT_EQ(rows.size(), 3u);
  const std::vector<std::string> header{
      "case_id",      "north",       "hour",        "Eavg_lx",         "Emin_lx",
      "Emax_lx",      "U0",          "Ud",          "DFavg_pct",       "DFmin_pct",
      "DFmedian_pct", "Esun_avg_lx", "Esun_max_lx", "sunlit_share_pct"};
  ASSERT_EQ(rows[0], header);
  std::vector<double> sunlit;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto& row = rows[i];
    SCOPED_TRACE(row[0]);
    const std::string alone = "alone-" + row[0];
    const Result grid =
        runPenumbra(dir.path(), "grid scene.yaml -o " + alone +
                                    " --device cpu -q --direct-only --set north=" + row[1] +
                                    " --set hour=" + row[2]);
    ASSERT_EQ(grid.status, 0) << grid.err;
    const auto summary = nlohmann::json::parse(readText(dir.path() / alone / "summary.json"));
    const auto& sun = summary["grids"][0]["sun"];
    const auto& df = summary["grids"][0]["daylight_factor"];
    EXPECT_EQ(row[8], fmt::format("{}", df["DFavg_pct"].get<double>()));
    EXPECT_EQ(row[11], fmt::format("{}", sun["Esun_avg_lx"].get<double>()));
    EXPECT_EQ(row[12], fmt::format("{}", sun["Esun_max_lx"].get<double>()));
    EXPECT_EQ(row[13], fmt::format("{}", sun["sunlit_share_pct"].get<double>()));
    // case.json holds the same figures, which the table is rebuilt from.
    const auto record =
        nlohmann::json::parse(readText(dir.path() / "out" / "cases" / row[0] / "case.json"));
    EXPECT_EQ(record["grids"][0]["Esun_avg_lx"], sun["Esun_avg_lx"]);
    EXPECT_EQ(record["grids"][0]["sunlit_share_pct"], sun["sunlit_share_pct"]);
    sunlit.push_back(std::stod(row[13]));
  }
  std::printf("  sunlit %.1f %% (window facing south), %.1f %% (west)\n", sunlit[0], sunlit[1]);
  // Facing south the morning sun comes in; facing west it is behind the facade.
  EXPECT_GT(sunlit[0], 0.0);
  EXPECT_EQ(sunlit[1], 0.0);
}

TEST(SweepCli, AKilledRunFinishedByARerunEqualsAnUninterruptedOne) {
  TempDir dir("penumbra-sweep-cli");
  write(dir.path() / "scene.yaml", scene(0.02));  // 300 × 200 points a case
  write(dir.path() / "study.yaml", kStudy);
  const fs::path cases = dir.path() / "killed" / "cases";
  {
    PenumbraProcess run(dir.path(), {"sweep", "study.yaml", "-o", "killed", "--device", "cpu"});
    ASSERT_TRUE(run.started());
    // A case folder appears only when the case is complete: kill as soon as one is there.
    while (run.running() && !fs::exists(cases / "case-001")) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    ASSERT_TRUE(run.running()) << "the whole run finished before the test could stop it";
    run.kill();
  }
  ASSERT_TRUE(fs::exists(cases / "case-001" / "case.json"));
  EXPECT_FALSE(fs::exists(cases / "case-006"));
  EXPECT_FALSE(fs::exists(dir.path() / "killed" / "results.csv"));  // the table comes last
  std::map<std::string, std::map<std::string, fs::file_time_type>> finished;
  for (const auto& entry : fs::directory_iterator(cases)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(".")) finished[name] = modificationTimes(entry.path());
  }
  ASSERT_FALSE(finished.empty());
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a rewrite would show in mtimes

  const Result rerun = runPenumbra(dir.path(), "sweep study.yaml -o killed --device cpu");
  ASSERT_EQ(rerun.status, 0) << rerun.err;
  EXPECT_NE(rerun.out.find(fmt::format("already finished {}", finished.size())), std::string::npos)
      << rerun.out;
  for (const auto& [name, times] : finished) {
    EXPECT_EQ(modificationTimes(cases / name), times) << name << " was touched";
  }
  const Result whole = runPenumbra(dir.path(), "sweep study.yaml -o whole --device cpu -q");
  ASSERT_EQ(whole.status, 0) << whole.err;
  EXPECT_EQ(readText(dir.path() / "killed" / "results.csv"),
            readText(dir.path() / "whole" / "results.csv"));
  EXPECT_EQ(readText(dir.path() / "killed" / "design-explorer.csv"),
            readText(dir.path() / "whole" / "design-explorer.csv"));
  // Nothing of the killed run's staging is left in the folders people read.
  for (const auto& entry : fs::directory_iterator(cases)) {
    EXPECT_TRUE(fs::exists(entry.path() / "case.json")) << entry.path();
  }
}

TEST(SweepCli, ShardsMergedEqualTheUnshardedRun) {
  TempDir dir("penumbra-sweep-cli");
  write(dir.path() / "scene.yaml", scene(0.5));
  write(dir.path() / "study.yaml", kStudy);
  for (const char* shard : {"1/2", "2/2"}) {
    const Result r = runPenumbra(dir.path(), fmt::format("sweep study.yaml -o shard-{} --shard {} "
                                                         "--device cpu",
                                                         shard[0], shard));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("not finished in this folder yet: 3 cases"), std::string::npos) << r.out;
  }
  EXPECT_EQ(csvRows(dir.path() / "shard-1" / "results.csv").size(), 4u);
  EXPECT_TRUE(fs::exists(dir.path() / "shard-1" / "cases" / "case-003"));
  EXPECT_FALSE(fs::exists(dir.path() / "shard-1" / "cases" / "case-002"));

  const Result merge = runPenumbra(dir.path(), "merge shard-1 shard-2 -o merged");
  ASSERT_EQ(merge.status, 0) << merge.err;
  const Result whole = runPenumbra(dir.path(), "sweep study.yaml -o whole --device cpu -q");
  ASSERT_EQ(whole.status, 0) << whole.err;
  for (const char* table : {"results.csv", "design-explorer.csv"}) {
    EXPECT_EQ(readText(dir.path() / "merged" / table), readText(dir.path() / "whole" / table))
        << table;
  }
  EXPECT_EQ(readText(dir.path() / "merged" / "cases" / "case-002" / "floor.csv"),
            readText(dir.path() / "whole" / "cases" / "case-002" / "floor.csv"));

  // Shards of another study do not mix.
  write(dir.path() / "other.yaml", std::string(kStudy) + "grids: [floor]\n");
  ASSERT_EQ(runPenumbra(dir.path(), "sweep other.yaml -o other --shard 1/2 --device cpu -q").status,
            0);
  const Result mixed = runPenumbra(dir.path(), "merge shard-1 other -o mixed");
  EXPECT_EQ(mixed.status, 1);
  EXPECT_NE(mixed.err.find("hold different sweeps"), std::string::npos) << mixed.err;
  EXPECT_FALSE(fs::exists(dir.path() / "mixed"));
}

TEST(SweepCli, AnInvalidCaseStopsTheStudyBeforeAnythingIsWritten) {
  TempDir dir("penumbra-sweep-cli");
  write(dir.path() / "scene.yaml", scene(0.5));
  write(dir.path() / "study.yaml", R"(penumbra-study: 1
scene: scene.yaml
parameters:
  flux: [3000, -1]
)");
  const Result r = runPenumbra(dir.path(), "sweep study.yaml -o out --device cpu");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("study.yaml:3: parameters: case-002 (flux = -1) makes an invalid scene: "
                       "scene.yaml:9: sources[0].flux: must not be negative (got -1 lm) "
                       "(sources[0].flux = ${flux} = -1; with flux = -1)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));

  write(dir.path() / "typo.yaml", "penumbra-study: 1\nscene: scene.yaml\nparameters: {flx: [1]}\n");
  const Result typo = runPenumbra(dir.path(), "sweep typo.yaml -o out");
  EXPECT_EQ(typo.status, 2);
  EXPECT_NE(typo.err.find("typo.yaml:3: parameters.flx: 'flx' is not a parameter of scene.yaml; "
                          "it declares: flux, x"),
            std::string::npos)
      << typo.err;
}

TEST(SweepCli, HelpTeaches) {
  TempDir dir("penumbra-sweep-cli");
  const Result sweep = runPenumbra(dir.path(), "sweep --help");
  EXPECT_EQ(sweep.status, 0);
  for (const char* words : {"--shard", "--resume", "results.csv", "Eavg_lx", "design-explorer.csv",
                            "penumbra merge", "Exit status", "--slurm", "--shards", "--slurm-opt",
                            "--dry-run", "sweep.sbatch", "merge.sbatch"}) {
    EXPECT_NE(sweep.out.find(words), std::string::npos) << words;
  }
  const Result merge = runPenumbra(dir.path(), "merge --help");
  EXPECT_EQ(merge.status, 0);
  EXPECT_NE(merge.out.find("shards"), std::string::npos) << merge.out;
}

}  // namespace
