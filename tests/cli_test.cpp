// The `penumbra` binary as a user runs it: exit codes, files, messages.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "penumbra_process.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;

using penumbra::testing::lines;
using penumbra::testing::readText;
using penumbra::testing::Result;
using penumbra::testing::runPenumbra;
using penumbra::testing::TempDir;

// A 4 × 4 × 3 m room, a 1 m² ceiling panel and a small table beside the point under it that
// shades part of the floor. The probe at (1.5, 1.5, 0.5) is inside the table. No floor point
// lies under the table (where the floor touches it).
constexpr const char* kScene = R"(penumbra: 1
room:
  size: [4.0, 4.0, 3.0]
  wall_thickness: 0.2
solids:
  - {name: table, box: {min: [1.3, 1.3, 0.0], max: [1.7, 1.7, 0.75]}}
sources:
  - {name: panel, polygon: [[1.5, 1.5, 3.0], [2.5, 1.5, 3.0], [2.5, 2.5, 3.0], [1.5, 2.5, 3.0]], normal: [0.0, 0.0, -1.0], luminance: 1000.0}
grids:
  - {name: floor, rect: {origin: [0.0, 0.0, 0.0], u: [4.0, 0, 0], v: [0, 4.0, 0]}, spacing: 0.5}
  - {name: probes, points: [[1.5, 1.5, 0.5, 0, 0, 1], [0.5, 0.5, 0.0, 0, 0, 1], [1.5, 1.5, 0.75, 0, 0, 1]]}
)";

void writeScene(const fs::path& file, const std::string& text = kScene) {
  std::ofstream(file) << text;
}

struct CsvRow {
  double x, y, z, e;
  std::string inside;
};

std::vector<CsvRow> readCsv(const fs::path& file) {
  std::vector<CsvRow> rows;
  const auto all = lines(readText(file));
  EXPECT_FALSE(all.empty());
  if (all.empty()) return rows;
  // With interreflection (the default) E_direct_lx and E_indirect_lx follow E_lx.
  const bool withParts = all[0] == "x_m,y_m,z_m,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,inside";
  if (!withParts) {
    EXPECT_EQ(all[0], "x_m,y_m,z_m,nx,ny,nz,E_lx,inside");
  }
  const std::size_t fields = withParts ? 10 : 8;
  for (std::size_t i = 1; i < all.size(); ++i) {
    std::vector<std::string> f(1);
    for (char c : all[i]) {
      if (c == ',') {
        f.emplace_back();
      } else {
        f.back() += c;
      }
    }
    EXPECT_EQ(f.size(), fields) << all[i];
    if (f.size() != fields) continue;
    rows.push_back(
        {std::stod(f[0]), std::stod(f[1]), std::stod(f[2]), std::stod(f[6]), f[fields - 1]});
  }
  return rows;
}

void expectCompleteResults(const fs::path& out, const std::string& estimator) {
  for (const char* name : {"floor.csv", "floor.res", "floor.pts", "probes.csv", "probes.res",
                           "probes.pts", "summary.json"}) {
    EXPECT_TRUE(fs::exists(out / name)) << name;
  }
  const auto floor = readCsv(out / "floor.csv");
  EXPECT_EQ(floor.size(), 64u);  // 8 × 8 cells of 0.5 m
  const auto res = lines(readText(out / "floor.res"));
  ASSERT_EQ(res.size(), floor.size());
  for (std::size_t i = 0; i < floor.size(); ++i) {
    EXPECT_EQ(std::stod(res[i]), floor[i].e) << "line " << i + 1;
  }
  // Row-major, x fastest: point (col, row) is at (0.25 + 0.5·col, 0.25 + 0.5·row). The table
  // top hides the whole panel from (1.25, 1.25) and part of it from (1.25, 1.75); the mirror
  // image of that one, (2.75, 1.75), sees all of it.
  const auto at = [&](int col, int row) { return floor.at(row * 8 + col); };
  EXPECT_EQ(at(2, 2).x, 1.25);
  EXPECT_EQ(at(2, 2).y, 1.25);
  EXPECT_EQ(at(2, 2).e, 0.0);
  EXPECT_GT(at(2, 3).e, 0.0);
  EXPECT_LT(at(2, 3).e, 0.99 * at(5, 3).e);
  const auto probes = readCsv(out / "probes.csv");
  ASSERT_EQ(probes.size(), 3u);
  EXPECT_EQ(probes[0].inside, "table");
  EXPECT_EQ(probes[0].e, 0.0);
  EXPECT_EQ(probes[1].inside, "");
  EXPECT_GT(probes[1].e, 0.0);
  EXPECT_EQ(probes[2].inside, "");  // on the table top, not inside it
  EXPECT_GT(probes[2].e, probes[1].e);

  const auto summary = nlohmann::json::parse(readText(out / "summary.json"));
  EXPECT_EQ(summary["estimator"], estimator);
  EXPECT_EQ(summary["scene"], "scene.yaml");
  ASSERT_EQ(summary["grids"].size(), 2u);
  EXPECT_EQ(summary["grids"][0]["name"], "floor");
  EXPECT_EQ(summary["grids"][0]["points"], 64);
  EXPECT_EQ(summary["grids"][0]["spacing_m"].get<double>(), 0.5);
  EXPECT_EQ(summary["grids"][1]["points"], 3);
  EXPECT_EQ(summary["grids"][1]["points_inside_solids"], 1);
  // The inside probe is left out: Emin is the floor probe's E.
  EXPECT_EQ(summary["grids"][1]["Emin_lx"].get<double>(), probes[1].e);
}

TEST(Cli, GridWithTheReferenceWritesEveryFile) {
  TempDir dir("penumbra-cli-test");
  writeScene(dir.path() / "scene.yaml");
  const Result r = runPenumbra(dir.path(), "grid scene.yaml -o out --reference --reference-n 16");
  ASSERT_EQ(r.status, 0) << r.err;
  expectCompleteResults(dir.path() / "out", "reference");
  // The table goes to stdout.
  EXPECT_NE(r.out.find("Eavg [lx]"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("probes"), std::string::npos);
}

TEST(Cli, GridWithTheKernelAgreesWithTheReference) {
  TempDir dir("penumbra-cli-test");
  writeScene(dir.path() / "scene.yaml");
  // The reference computes direct light only.
  const Result kernel =
      runPenumbra(dir.path(), "grid scene.yaml -o kernel --device cpu -q --direct-only");
  if (kernel.status != 0 && kernel.err.find("no OpenCL device") != std::string::npos) {
    GTEST_SKIP() << "no OpenCL CPU device: " << kernel.err;
  }
  ASSERT_EQ(kernel.status, 0) << kernel.err;
  EXPECT_TRUE(kernel.out.empty()) << "--quiet prints nothing: " << kernel.out;
  expectCompleteResults(dir.path() / "kernel", "kernel");
  const Result reference =
      runPenumbra(dir.path(), "grid scene.yaml -o reference --reference --reference-n 256 -q");
  ASSERT_EQ(reference.status, 0) << reference.err;
  const auto a = readCsv(dir.path() / "kernel" / "floor.csv");
  const auto b = readCsv(dir.path() / "reference" / "floor.csv");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    // The reference's error is O(1/n²) where a point sees the whole panel but O(1/n) in the
    // table's penumbra; tests/reference_test.cpp and the kernel tests hold both to tighter bounds.
    EXPECT_NEAR(a[i].e, b[i].e, 1e-2 * b[i].e) << a[i].x << " " << a[i].y;
  }
}

// EN 17037 through the daylight factor, end to end: a small window in a room seen direct only
// (a black room), E_v,d,med = 10 000 lx = E_h, so DF = E / 100 and the minimum level's targets are
// D_T = 3 % and D_TM = 1 %. The shares in summary.json against the shares counted here from the
// CSV's DF_pct column.
TEST(Cli, DaylightProvisionSharesMatchTheCsvDfColumn) {
  TempDir dir("penumbra-cli-test");
  writeScene(dir.path() / "scene.yaml", R"(penumbra: 1
site: {latitude_deg: 51.5, longitude_deg: -0.1, median_diffuse_illuminance_lx: 10000}
sky: {model: cie-overcast, horizontal_illuminance_lx: 10000, ground_reflectance: 0.2}
room:
  size: [4.0, 4.0, 3.0]
  wall_thickness: 0.2
  openings:
    - {name: w1, wall: y0, x: 1.5, z: 0.9, width: 1.0, height: 1.2}
grids:
  - {name: reference-plane, height: 0.85, spacing: 0.5, margin: 0.5}
)");
  const Result r = runPenumbra(dir.path(), "grid scene.yaml -o out --device cpu --direct-only");
  if (r.status != 0 && r.err.find("no OpenCL device") != std::string::npos) {
    GTEST_SKIP() << "no OpenCL CPU device: " << r.err;
  }
  ASSERT_EQ(r.status, 0) << r.err;
  const auto all = lines(readText(dir.path() / "out" / "reference-plane.csv"));
  ASSERT_EQ(all.at(0), "x_m,y_m,z_m,nx,ny,nz,E_lx,DF_pct,inside");
  std::vector<double> df;
  for (std::size_t i = 1; i < all.size(); ++i) {
    std::stringstream row(all[i]);
    std::string cell;
    for (int c = 0; c <= 7; ++c) std::getline(row, cell, ',');
    df.push_back(std::stod(cell));
  }
  ASSERT_FALSE(df.empty());
  const auto share = [&](double target) {
    std::size_t n = 0;
    for (double d : df) n += d >= target ? 1 : 0;
    return 100.0 * static_cast<double>(n) / static_cast<double>(df.size());
  };
  const nlohmann::json summary =
      nlohmann::json::parse(readText(dir.path() / "out" / "summary.json"));
  const nlohmann::json& en = summary["grids"][0]["daylight_factor"]["en17037"];
  EXPECT_EQ(en["median_diffuse_illuminance_lx"].get<double>(), 10000.0);
  const double targets[][2] = {{3.0, 1.0}, {5.0, 3.0}, {7.5, 5.0}};  // %: D_T, D_TM
  std::string reached = "none";
  for (std::size_t k = 0; k < 3; ++k) {
    const nlohmann::json& level = en["levels"][k];
    EXPECT_NEAR(level["DF_target_pct"].get<double>(), targets[k][0], 1e-12);
    EXPECT_NEAR(level["DF_minimum_target_pct"].get<double>(), targets[k][1], 1e-12);
    // The CSV's DF is written to its digits: a point within them of a target could count on
    // either side, so the shares agree to one point.
    const double step = 100.0 / static_cast<double>(df.size());
    EXPECT_NEAR(level["share_at_least_target_pct"].get<double>(), share(targets[k][0]), step);
    EXPECT_NEAR(level["share_at_least_minimum_target_pct"].get<double>(), share(targets[k][1]),
                step);
    const bool met = share(targets[k][0]) >= 50.0 && share(targets[k][1]) >= 95.0;
    EXPECT_EQ(level["met"].get<bool>(), met) << level;
    if (met) reached = level["level"].get<std::string>();
  }
  EXPECT_EQ(en["level_reached"].get<std::string>(), reached);
  std::printf("  EN 17037 over %zu points: DF >= 3 %% on %.1f %%, >= 1 %% on %.1f %%: %s\n",
              df.size(), share(3.0), share(1.0), reached.c_str());
  EXPECT_NE(r.out.find("EN 17037 daylight provision reached: " + reached), std::string::npos)
      << r.out;
}

// --no-culling runs the plain path (every occluder at every point): the same numbers, and the
// summary says which path ran.
TEST(Cli, NoCullingGivesTheSameIlluminance) {
  TempDir dir("penumbra-cli-test");
  writeScene(dir.path() / "scene.yaml");
  const Result culled = runPenumbra(dir.path(), "grid scene.yaml -o culled --device cpu -q");
  if (culled.status != 0 && culled.err.find("no OpenCL device") != std::string::npos) {
    GTEST_SKIP() << "no OpenCL CPU device: " << culled.err;
  }
  ASSERT_EQ(culled.status, 0) << culled.err;
  const Result plain =
      runPenumbra(dir.path(), "grid scene.yaml -o plain --device cpu -q --no-culling");
  ASSERT_EQ(plain.status, 0) << plain.err;
  const auto a = readCsv(dir.path() / "culled" / "floor.csv");
  const auto b = readCsv(dir.path() / "plain" / "floor.csv");
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i].e, b[i].e, 1e-6 * b[i].e) << i;
  const auto summary = nlohmann::json::parse(readText(dir.path() / "plain" / "summary.json"));
  EXPECT_NE(summary.dump().find("no culling"), std::string::npos) << summary.dump();
}

// By default E is the total: the CSV's E_direct_lx is, byte for byte, what --direct-only writes
// as E_lx, E_indirect_lx is the rest, and the outputs say which they hold. A scene whose lit
// solids have no material gets a warning naming them.
TEST(Cli, TotalIlluminanceBesideItsDirectPart) {
  TempDir dir("penumbra-cli-test");
  std::string scene = kScene;
  scene.replace(scene.find("  wall_thickness: 0.2\n"), 21,
                "  wall_thickness: 0.2\n  materials: {floor: paint, ceiling: paint, walls: "
                "paint}\n");
  writeScene(dir.path() / "scene.yaml", "materials: {paint: 0.6}\n" + scene);
  const Result total = runPenumbra(dir.path(), "grid scene.yaml -o total --device cpu");
  if (total.status != 0 && total.err.find("no OpenCL device") != std::string::npos) {
    GTEST_SKIP() << "no OpenCL CPU device: " << total.err;
  }
  ASSERT_EQ(total.status, 0) << total.err;
  EXPECT_NE(total.out.find("E: total illuminance (direct + interreflected)"), std::string::npos)
      << total.out;
  EXPECT_NE(total.err.find("without a material"), std::string::npos) << total.err;  // the table
  const Result direct =
      runPenumbra(dir.path(), "grid scene.yaml -o direct --device cpu -q --direct-only");
  ASSERT_EQ(direct.status, 0) << direct.err;

  const auto fields = [](const std::string& line) {
    std::vector<std::string> f(1);
    for (char c : line) {
      if (c == ',') {
        f.emplace_back();
      } else {
        f.back() += c;
      }
    }
    return f;
  };
  const auto totalRows = lines(readText(dir.path() / "total" / "floor.csv"));
  const auto directRows = lines(readText(dir.path() / "direct" / "floor.csv"));
  ASSERT_EQ(totalRows.size(), directRows.size());
  EXPECT_EQ(totalRows[0], "x_m,y_m,z_m,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,inside");
  EXPECT_EQ(directRows[0], "x_m,y_m,z_m,nx,ny,nz,E_lx,inside");
  for (std::size_t i = 1; i < totalRows.size(); ++i) {
    const auto t = fields(totalRows[i]), d = fields(directRows[i]);
    ASSERT_EQ(t.size(), 10u);
    EXPECT_EQ(t[7], d[6]) << i;  // the same digits
    const double e = std::stod(t[6]), eDirect = std::stod(t[7]), eIndirect = std::stod(t[8]);
    // Each written with its float's digits, rounded by at most half an ulp of a value no larger
    // than E: the three agree to 2^-23 of E.
    EXPECT_NEAR(eIndirect, e - eDirect, 0x1p-23 * e) << i;
    if (t[9].empty()) {
      EXPECT_GT(eIndirect, 0.0) << i;  // the walls light every floor point
    }
  }
  const auto summary = nlohmann::json::parse(readText(dir.path() / "total" / "summary.json"));
  EXPECT_EQ(summary["illuminance"], "total (direct + interreflected)");
  EXPECT_GT(summary["interreflection"]["elements"].get<int>(), 0);
  EXPECT_LE(summary["interreflection"]["relative_residual"].get<double>(), 1e-9);
  // The table (a solid without material) is black, and named.
  EXPECT_EQ(summary["interreflection"]["solids_without_material"], nlohmann::json({"table"}));
  EXPECT_LT(summary["grids"][0]["direct"]["Eavg_lx"].get<double>(),
            summary["grids"][0]["Eavg_lx"].get<double>());
  const auto plain = nlohmann::json::parse(readText(dir.path() / "direct" / "summary.json"));
  EXPECT_EQ(plain["illuminance"], "direct only");
  EXPECT_FALSE(plain.contains("interreflection"));
  EXPECT_EQ(plain["grids"][0]["Eavg_lx"], summary["grids"][0]["direct"]["Eavg_lx"]);
}

TEST(Cli, OnlyTheGridsAskedFor) {
  TempDir dir("penumbra-cli-test");
  writeScene(dir.path() / "scene.yaml");
  const Result r = runPenumbra(
      dir.path(), "grid --grid probes scene.yaml -o out --reference --reference-n 8 -q");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir.path() / "out" / "probes.csv"));
  EXPECT_FALSE(fs::exists(dir.path() / "out" / "floor.csv"));
  const auto summary = nlohmann::json::parse(readText(dir.path() / "out" / "summary.json"));
  EXPECT_EQ(summary["grids"].size(), 1u);
}

TEST(Cli, AnUnknownGridIsAnErrorAndWritesNothing) {
  TempDir dir("penumbra-cli-test");
  writeScene(dir.path() / "scene.yaml");
  const Result r = runPenumbra(dir.path(), "grid scene.yaml -o out --reference --grid ceiling");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("ceiling"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("floor"), std::string::npos) << "lists the grids there are: " << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(Cli, ASceneErrorExitsWithTwoAndWritesNothing) {
  TempDir dir("penumbra-cli-test");
  std::string text = kScene;
  text.replace(text.find("luminance: 1000.0"), 17, "luminance: -1.0");
  writeScene(dir.path() / "scene.yaml", text);
  const Result r = runPenumbra(dir.path(), "grid scene.yaml -o out/nested --reference");
  EXPECT_EQ(r.status, 2) << r.err;
  // file:line: key: message, the line being the one of the source.
  EXPECT_NE(r.err.find("scene.yaml:8: sources[0].luminance: "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
  std::vector<fs::path> left;
  for (const auto& entry : fs::directory_iterator(dir.path())) left.push_back(entry.path());
  EXPECT_EQ(left.size(), 1u) << "only scene.yaml";
}

TEST(Cli, ASourceThatLightsNothingIsWarnedInTheTerminalAndTheSummary) {
  TempDir dir("penumbra-cli-test");
  std::string text = kScene;
  text.replace(text.find("normal: [0.0, 0.0, -1.0]"), 24, "normal: [0.0, 0.0, 1.0]");
  writeScene(dir.path() / "scene.yaml", text);
  const Result r = runPenumbra(dir.path(), "grid scene.yaml -o out --reference --reference-n 4");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string expected =
      "scene.yaml:8: warning: sources[0]: source 'panel' lights nothing: it emits towards [0, 0, "
      "1]";
  EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
  const auto summary = nlohmann::json::parse(readText(dir.path() / "out" / "summary.json"));
  ASSERT_EQ(summary["warnings"].size(), 1u);
  EXPECT_TRUE(summary["warnings"][0].get<std::string>().starts_with(expected))
      << summary["warnings"];
  // Nothing is lit.
  EXPECT_EQ(summary["grids"][0]["Emax_lx"].get<double>(), 0.0);
}

TEST(Cli, AValidSceneHasAnEmptyWarningsList) {
  TempDir dir("penumbra-cli-test");
  writeScene(dir.path() / "scene.yaml");
  const Result r = runPenumbra(dir.path(), "grid scene.yaml -o out --reference --reference-n 4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
  const auto summary = nlohmann::json::parse(readText(dir.path() / "out" / "summary.json"));
  EXPECT_TRUE(summary["warnings"].is_array());
  EXPECT_TRUE(summary["warnings"].empty());
}

TEST(Cli, AMissingSceneFileIsAnError) {
  TempDir dir("penumbra-cli-test");
  const Result r = runPenumbra(dir.path(), "grid missing.yaml -o out --reference");
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("missing.yaml"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(Cli, AnExistingOutputDirectoryKeepsOtherFiles) {
  TempDir dir("penumbra-cli-test");
  writeScene(dir.path() / "scene.yaml");
  fs::create_directories(dir.path() / "out");
  std::ofstream(dir.path() / "out" / "README") << "my notes";
  const Result r =
      runPenumbra(dir.path(), "grid scene.yaml -o out/ --reference --reference-n 8 -q");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readText(dir.path() / "out" / "README"), "my notes");
  EXPECT_TRUE(fs::exists(dir.path() / "out" / "summary.json"));
}

TEST(Cli, HelpTeachesUnitsAndOutputs) {
  TempDir dir("penumbra-cli-test");
  const Result top = runPenumbra(dir.path(), "--help");
  EXPECT_EQ(top.status, 0);
  EXPECT_NE(top.out.find("lx"), std::string::npos) << top.out;
  EXPECT_NE(top.out.find("grid"), std::string::npos);
  EXPECT_NE(top.out.find("devices"), std::string::npos);
  const Result grid = runPenumbra(dir.path(), "grid --help");
  EXPECT_EQ(grid.status, 0);
  for (const char* word : {"E_lx", "E_direct_lx", "E_indirect_lx", ".res", "summary.json",
                           "Eavg_lx", "--reference-n", "--grid", "--device", "--direct-only",
                           "--element-size", "penumbra grid data/office.yaml -o out/office"}) {
    EXPECT_NE(grid.out.find(word), std::string::npos) << word;
  }
}

TEST(Cli, VersionAndUsageErrors) {
  TempDir dir("penumbra-cli-test");
  const Result version = runPenumbra(dir.path(), "--version");
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.out.rfind("penumbra ", 0), 0u) << version.out;
  EXPECT_EQ(runPenumbra(dir.path(), "").status, 1);                 // a subcommand is required
  EXPECT_EQ(runPenumbra(dir.path(), "grid scene.yaml").status, 1);  // -o is required
  EXPECT_EQ(runPenumbra(dir.path(), "frobnicate").status, 1);
}

TEST(Cli, DevicesListsWhatGridCanUse) {
  TempDir dir("penumbra-cli-test");
  const Result r = runPenumbra(dir.path(), "devices");
  if (r.status == 1) GTEST_SKIP() << "no OpenCL device: " << r.err;
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = lines(r.out);
  ASSERT_GE(rows.size(), 2u);
  for (const char* column :
       {"Index", "Type", "Name", "Platform", "Compute units", "Memory [MB]", "Largest buffer"}) {
    EXPECT_NE(rows[0].find(column), std::string::npos) << column;
  }
}

}  // namespace
