// `penumbra luminaire FILE` as a user runs it: what it prints for the example luminaires, its
// help, and its exit status and message for files it cannot read.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "penumbra_process.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;

using penumbra::testing::Result;
using penumbra::testing::runPenumbra;
using penumbra::testing::TempDir;

const fs::path kExamples = fs::path(PENUMBRA_SOURCE_DIR) / "data/luminaires";

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Runs `penumbra luminaire` on the example `name` and expects each of `lines` in its output.
void expectReport(const std::string& name, std::initializer_list<const char*> lines) {
  TempDir dir("luminaire-cli");
  const Result r = runPenumbra(dir.path(), "luminaire '" + (kExamples / name).string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  for (const char* line : lines) EXPECT_TRUE(contains(r.out, line)) << line << "\n" << r.out;
}

TEST(LuminaireCommand, DescribesTheDownlight) {
  expectReport(
      "narrow-downlight.ies",
      {"IES LM-63-2002", "photometric type  C", "rotational (one plane)",
       "1 C plane (0°), 91 γ angles (0° to 90°)", "= 2000.0 lm", "LOR               85.00 %",
       "disk, length 0.080 m (C0-C180) x width 0.080 m", "at C 0°, γ 0°",
       "1700.0 lm = lamp lumens x LOR", "(within 0.1 %)", "warnings          none"});
}

TEST(LuminaireCommand, DescribesTheBatwingInEulumdat) {
  expectReport("batwing.ldt", {"format            EULUMDAT\n", "quadrant (C0-C90 stored)",
                               "7 C planes (0° to 90°), 37 γ angles (0° to 180°)",
                               "2 x LED strip (4400 lm for the set) = 4400.0 lm",
                               "rectangle, length 1.200 m (C0-C180) x width 0.150 m",
                               "at C 90°, γ 50°", "3960.0 lm = lamp lumens x LOR"});
}

TEST(LuminaireCommand, MalformedFileIsStatusTwoWithFileLineAndField) {
  TempDir dir("luminaire-cli");
  std::ofstream(dir.path() / "cut.ies")
      << "IESNA:LM-63-2002\n[TEST] x\nTILT=NONE\n1 1000 1 3 1 1 2 0 0 0\n1 1 10\n0 45\n";
  const Result r = runPenumbra(dir.path(), "luminaire cut.ies");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "cut.ies:6: vertical angles: expected 3 values, found 2 (the file ends)\n");
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(LuminaireCommand, UnknownExtensionAndMissingFileAreStatusOne) {
  TempDir dir("luminaire-cli");
  std::ofstream(dir.path() / "lamp.txt") << "hello\n";
  const Result unknown = runPenumbra(dir.path(), "luminaire lamp.txt");
  EXPECT_EQ(unknown.status, 1);
  EXPECT_TRUE(contains(unknown.err, "lamp.txt: unknown photometric format")) << unknown.err;
  const Result missing = runPenumbra(dir.path(), "luminaire none.ldt");
  EXPECT_EQ(missing.status, 1);
  EXPECT_EQ(missing.err, "none.ldt: cannot be read\n");
}

TEST(LuminaireCommand, HelpExplainsTheLines) {
  TempDir dir("luminaire-cli");
  const Result r = runPenumbra(dir.path(), "luminaire --help");
  EXPECT_EQ(r.status, 0);
  for (const char* part : {"IES LM-63", "EULUMDAT", "cd/klm", "zonal method", "lamp lumens x LOR",
                           "docs/photometry.md", "Exit status"}) {
    EXPECT_TRUE(contains(r.out, part)) << part << "\n" << r.out;
  }
}

// A scene with luminaires of the area model: the device and `--reference` evaluate it, and
// summary.json lists its model and fit.
void writeAreaScene(const fs::path& dir) {
  std::ofstream(dir / "scene.yaml") << "penumbra: 1\n"
                                       "luminaires:\n"
                                       "  - name: panel\n"
                                       "    file: '" +
                                           (kExamples / "lambertian-panel.ldt").string() +
                                           "'\n"
                                           "    position: [1, 1, 2.9]\n"
                                           "    model: area\n"
                                           "  - name: washer\n"
                                           "    file: '" +
                                           (kExamples / "asymmetric-wallwasher.ies").string() +
                                           "'\n"
                                           "    position: [2, 1, 2.9]\n"
                                           "    model: area\n"
                                           "grids:\n"
                                           "  - {name: floor, rect: {origin: [0, 0, 0], u: [2, 0, "
                                           "0], v: [0, 2, 0]}, spacing: 0.5}\n";
}

TEST(LuminaireAreaModel, TheReferenceRunsItAndTheSummaryListsTheFit) {
  TempDir dir("luminaire-cli");
  writeAreaScene(dir.path());
  const Result r = runPenumbra(dir.path(), "grid scene.yaml -o out --reference -q");
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(dir.path() / "out" / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  const nlohmann::json& panel = summary.at("luminaires").at(0);
  EXPECT_EQ(panel.at("model"), "area");
  EXPECT_EQ(panel.at("fit_order"), 0);
  EXPECT_LT(panel.at("fit_error").get<double>(), 1e-3);
  EXPECT_EQ(panel.at("parts"), nlohmann::json::array({1, 1}));
  // The wall-washer's lobe is not symmetric about its nadir: split into cells.
  const nlohmann::json& washer = summary.at("luminaires").at(1);
  EXPECT_GT(washer.at("fit_error").get<double>(), 0.01);
  EXPECT_EQ(washer.at("parts"), nlohmann::json::array({3, 3}));
}

TEST(LuminaireAreaModel, TheDeviceRunsItAndAgreesWithTheReference) {
  TempDir dir("luminaire-cli");
  writeAreaScene(dir.path());
  const Result device = runPenumbra(dir.path(), "grid scene.yaml -o device --device cpu -q");
  ASSERT_EQ(device.status, 0) << device.err;
  const Result reference = runPenumbra(dir.path(), "grid scene.yaml -o reference --reference -q");
  ASSERT_EQ(reference.status, 0) << reference.err;
  const auto eAvg = [&](const char* out) {
    std::ifstream in(dir.path() / out / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(in);
    EXPECT_EQ(summary.at("luminaires").at(0).at("model"), "area");
    return summary.at("grids").at(0).at("Eavg_lx").get<double>();
  };
  const double fromDevice = eAvg("device"), fromReference = eAvg("reference");
  EXPECT_GT(fromReference, 0.0);
  EXPECT_NEAR(fromDevice, fromReference, 1e-5 * fromReference);
}

// Two downlights with maintenance factors `first` and `second` over a 2 × 2 m floor grid.
void writeMaintainedScene(const fs::path& dir, double first, double second) {
  std::ofstream scene(dir / "scene.yaml");
  scene << "penumbra: 1\nluminaires:\n";
  for (const int k : {1, 2}) {
    scene << "  - {name: light-" << k << ", file: '"
          << (kExamples / "narrow-downlight.ies").string() << "', position: [" << k
          << ", 1, 2.9], maintenance_factor: " << (k == 1 ? first : second) << "}\n";
  }
  scene << "grids:\n  - {name: floor, rect: {origin: [0, 0, 0], u: [2, 0, 0], v: [0, 2, 0]}, "
           "spacing: 0.5}\n";
}

// The first line of the printed table and summary.json's "illuminance" say what E includes: the
// maintenance factor where one is below 1, and the values do include it.
TEST(LuminaireMaintenance, TheTableAndTheSummarySayWhatEIncludes) {
  TempDir dir("luminaire-cli");
  const auto run = [&](double first, double second, const std::string& out) {
    writeMaintainedScene(dir.path(), first, second);
    const Result r = runPenumbra(dir.path(), "grid scene.yaml -o " + out + " --reference");
    EXPECT_EQ(r.status, 0) << r.err;
    std::ifstream in(dir.path() / out / "summary.json");
    const nlohmann::json summary = nlohmann::json::parse(in);
    return std::make_tuple(r.out.substr(0, r.out.find('\n')), summary.at("illuminance"),
                           summary.at("grids").at(0).at("Eavg_lx").get<double>());
  };
  const auto [newTable, newSummary, newAvg] = run(1.0, 1.0, "new");
  EXPECT_EQ(newTable, "E: direct illuminance only");
  EXPECT_EQ(newSummary, "direct only");

  const auto [table, summary, eAvg] = run(0.8, 0.8, "maintained");
  EXPECT_EQ(table, "E: direct illuminance only, maintained, MF 0.8");
  EXPECT_EQ(summary, "direct only, maintained, MF 0.8");
  EXPECT_NEAR(eAvg, 0.8 * newAvg, 1e-12 * newAvg);

  const auto [eachTable, eachSummary, eachAvg] = run(0.8, 0.9, "each");
  EXPECT_EQ(eachTable,
            "E: direct illuminance only, maintained (MF per luminaire: light-1 0.8, "
            "light-2 0.9)");
  EXPECT_EQ(eachSummary, "direct only, maintained (MF per luminaire: light-1 0.8, light-2 0.9)");
  EXPECT_LT(eachAvg, 0.9 * newAvg);
  EXPECT_GT(eachAvg, 0.8 * newAvg);
}

// --ugr-table prints the two tables (S = 0.25H and 1.0H) and -o writes them as one CSV: 2 x 19
// rows, whose cells are the printed ones to the printed digit.
TEST(LuminaireCommand, UgrTableIsPrintedAndWrittenAsCsv) {
  TempDir dir("luminaire-cli");
  const Result r =
      runPenumbra(dir.path(), "luminaire '" + (kExamples / "lambertian-panel.ldt").string() +
                                  "' --ugr-table -o ugr");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "UGR [-] table, S = 0.25H, H = 2.00 m (CIE 190:2010 tabular"));
  EXPECT_TRUE(contains(r.out, "UGR [-] table, S = 1.00H"));
  EXPECT_TRUE(contains(r.out, "for a flux Phi add 8 log10(Phi/Phi0)"));
  std::ifstream in(dir.path() / "ugr" / "lambertian-panel-ugr-table.csv");
  ASSERT_TRUE(in) << r.out;
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header.substr(0, 62), "S_over_H,X_H,Y_H,X_m,Y_m,luminaires,UGR_crosswise_70_50_20,UGR");
  int rows = 1;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 38);
  // 0.25,2,2,4,4,64,<UGR crosswise 70/50/20>,... against the printed "2H    2H    <UGR>".
  std::vector<std::string> cells;
  std::stringstream fields(first);
  for (std::string cell; std::getline(fields, cell, ',');) cells.push_back(cell);
  ASSERT_GE(cells.size(), 7u);
  EXPECT_EQ(cells[5], "64");  // (4 m / 0.5 m)²
  const std::string printed = fmt::format("  2H    2H        {:>6.1f}", std::stod(cells[6]));
  EXPECT_TRUE(contains(r.out, printed)) << printed << "\n" << r.out;
}

TEST(LuminaireCommand, UgrTableOfAFileWithoutLuminousAreaIsRefused) {
  TempDir dir("luminaire-cli");
  std::ofstream(dir.path() / "point.ies")
      << "IESNA:LM-63-2002\n[TEST] x\nTILT=NONE\n1 1000 1 3 1 1 2 0 0 0\n1 1 10\n0 45 90\n0\n"
         "100 70 0\n";
  const Result r = runPenumbra(dir.path(), "luminaire point.ies --ugr-table");
  EXPECT_EQ(r.status, 1);
  EXPECT_TRUE(contains(r.err, "point.ies: no luminous area to rate")) << r.err;
}

}  // namespace
