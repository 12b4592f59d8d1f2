// The scene's `luminaires:` key: what it builds (files relative to the scene, arrays, the flux
// override and the maintenance factor, parameters) and one test per validation error, each
// asserting the line and key path it names.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "photometry_files.hpp"
#include "reference/luminaire_illuminance.hpp"
#include "scene/scene_loader.hpp"
#include "scene_errors.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// A scene beside data/luminaires/, so that `file: luminaires/…` finds the example files.
const fs::path kDataScene = fs::path(PENUMBRA_SOURCE_DIR) / "data" / "luminaire-test.yaml";

std::string sceneWith(const std::string& luminaire) {
  return "penumbra: 1\n"
         "parameters: {h: 2.9}\n"
         "luminaires:\n" +
         luminaire;
}

SceneError errorOf(const std::string& yaml, const fs::path& file = kDataScene) {
  return testing::sceneErrorOf(yaml, file);
}

void expectError(const std::string& luminaire, int line, const std::string& key,
                 const std::string& words) {
  const SceneError e = errorOf(sceneWith(luminaire));
  EXPECT_EQ(e.line(), line) << e.what();
  EXPECT_EQ(e.key(), key) << e.what();
  EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
}

TEST(LuminaireScene, AnArrayExpandsIntoNamedInstances) {
  const Scene scene = parseScene(sceneWith("  - name: row-a\n"
                                           "    file: luminaires/narrow-downlight.ies\n"
                                           "    position: [1.5, 2.0, \"${h}\"]\n"
                                           "    aim: {rotate_deg: 90, tilt_deg: 0}\n"
                                           "    array: {count: [3, 2], spacing: [1.8, 2.0]}\n"),
                                 kDataScene);
  ASSERT_EQ(scene.luminaires.size(), 1u);
  const Luminaire& l = scene.luminaires.front();
  ASSERT_EQ(l.instances.size(), 6u);
  EXPECT_EQ(l.instances[0].name, "row-a[1,1]");
  EXPECT_EQ(l.instances[5].name, "row-a[3,2]");
  EXPECT_TRUE(l.instances[5].position.isApprox(Vec3(1.5 + 2 * 1.8, 4.0, 2.9)));
  // rotate 90: C0 (local x) along the scene's +y, C90 along −x.
  EXPECT_TRUE((l.instances[0].toScene * Vec3::UnitX()).isApprox(Vec3::UnitY()));
  EXPECT_TRUE((l.instances[0].toScene * Vec3::UnitY()).isApprox(-Vec3::UnitX()));
  EXPECT_EQ(l.model, LuminaireModel::Area);  // the file gives an opening (a disk)
  EXPECT_EQ(l.maintenanceFactor, 1.0);
  EXPECT_EQ(l.lampLumens, 2000.0);  // the file's
}

TEST(LuminaireScene, FluxOverrideAndMaintenanceFactorScaleTheIntensities) {
  const std::string plain =
      "  - {name: d, file: luminaires/narrow-downlight.ies, "
      "position: [0, 0, 3]}\n";
  const std::string scaled =
      "  - {name: d, file: luminaires/narrow-downlight.ies, "
      "position: [0, 0, 3], flux_lm: 1500, maintenance_factor: 0.8}\n";
  const Scene a = parseScene(sceneWith(plain), kDataScene);
  const Scene b = parseScene(sceneWith(scaled), kDataScene);
  EXPECT_EQ(b.luminaires.front().lampLumens, 1500.0);
  const SamplePoint point{Vec3(0.3, 0.2, 0), Vec3::UnitZ(), -1};
  const double ea = referenceLuminaireIlluminance(a, {&point, 1})[0];
  const double eb = referenceLuminaireIlluminance(b, {&point, 1})[0];
  // 1500 / 2000 of the lamp, times 0.8.
  EXPECT_NEAR(eb / ea, 0.75 * 0.8, 1e-14);
  EXPECT_NEAR(b.luminaires.front().zonalFluxLm() / a.luminaires.front().zonalFluxLm(), 0.75, 1e-14);
}

TEST(LuminaireScene, AMissingFileNamesTheKeyAndTheFile) {
  expectError("  - {name: d, file: luminaires/none.ies, position: [0, 0, 3]}\n", 4,
              "luminaires[0].file", "none.ies");
}

TEST(LuminaireScene, AMalformedFileGivesThePhotometricReadersError) {
  testing::TempDir dir("luminaire-scene");
  std::ofstream(dir.path() / "bad.ies") << "IESNA:LM-63-2002\nTILT=NONE\n1 1000 1 3 1 1 2 0 0 0\n"
                                           "1 1 10\n0 45 90\n0\n100 -3 20\n";
  const SceneError e = errorOf(sceneWith("  - {name: d, file: bad.ies, position: [0, 0, 3]}\n"),
                               dir.path() / "scene.yaml");
  EXPECT_EQ(e.line(), 4) << e.what();
  EXPECT_EQ(e.key(), "luminaires[0].file");
  // The reader's own "file:line: field: message".
  EXPECT_NE(std::string(e.what()).find("bad.ies:7: candela"), std::string::npos) << e.what();
}

TEST(LuminaireScene, BadAimValuesAreErrorsAtTheirKey) {
  expectError(
      "  - name: d\n"
      "    file: luminaires/narrow-downlight.ies\n"
      "    position: [0, 0, 3]\n"
      "    aim: {rotate_deg: ninety}\n",
      7, "luminaires[0].aim.rotate_deg", "expected a number");
  expectError(
      "  - name: d\n"
      "    file: luminaires/narrow-downlight.ies\n"
      "    position: [0, 0, 3]\n"
      "    aim: {rotate_deg: 0, tilt_deg: 900}\n",
      7, "luminaires[0].aim.tilt_deg", "[-360, 360]");
  expectError(
      "  - name: d\n"
      "    file: luminaires/narrow-downlight.ies\n"
      "    position: [0, 0, 3]\n"
      "    aim: {turn: 10}\n",
      7, "luminaires[0].aim.turn", "rotate_deg, tilt_deg");
}

TEST(LuminaireScene, ANegativeMaintenanceFactorIsAnError) {
  expectError(
      "  - name: d\n"
      "    file: luminaires/narrow-downlight.ies\n"
      "    position: [0, 0, 3]\n"
      "    maintenance_factor: -0.2\n",
      7, "luminaires[0].maintenance_factor", "lies in (0, 1], got -0.2");
  expectError(
      "  - {name: d, file: luminaires/narrow-downlight.ies, position: [0, 0, 3], "
      "maintenance_factor: 80}\n",
      4, "luminaires[0].maintenance_factor", "(0, 1]");
}

TEST(LuminaireScene, TheAreaModelTakesTheFilesOpeningAndFitsItsLuminance) {
  const Scene scene = parseScene(sceneWith("  - name: panel\n"
                                           "    file: luminaires/lambertian-panel.ldt\n"
                                           "    position: [1, 1, 2.9]\n"
                                           "    model: area\n"),
                                 kDataScene);
  const Luminaire& l = scene.luminaires.front();
  EXPECT_EQ(l.model, LuminaireModel::Area);
  ASSERT_TRUE(l.opening.has_value());
  EXPECT_EQ(l.opening->outline.size(), 4u);  // the 600 × 600 mm rectangle
  EXPECT_NEAR(l.opening->fit.openingAreaM2, 0.36, 1e-12);
  EXPECT_EQ(l.opening->fit.order(), 0);
  EXPECT_FALSE(l.opening->subdivided());
}

// Writes dir/point.ies: a file whose opening is a point (width, length and height 0).
void writePointIes(const fs::path& dir) {
  photometry::testfiles::IesSpec point;
  point.vertical = photometry::testfiles::steps(0, 90, 10);
  point.horizontal = {0};
  point.candela = [](double, double) { return 100.0; };
  std::ofstream(dir / "point.ies") << photometry::testfiles::iesText(point);
}

TEST(LuminaireScene, TheAreaModelNeedsAFlatOpening) {
  testing::TempDir dir("luminaire-scene");
  writePointIes(dir.path());
  const SceneError e = errorOf(sceneWith("  - name: p\n"
                                         "    file: point.ies\n"
                                         "    position: [0, 0, 3]\n"
                                         "    model: area\n"),
                               dir.path() / "scene.yaml");
  EXPECT_EQ(e.line(), 7) << e.what();
  EXPECT_EQ(e.key(), "luminaires[0].model") << e.what();
  EXPECT_NE(std::string(e.what()).find("no flat luminous opening"), std::string::npos) << e.what();
}

TEST(LuminaireScene, TheDefaultModelIsAreaWhereTheFileGivesAFlatOpening) {
  testing::TempDir dir("luminaire-scene");
  writePointIes(dir.path());
  std::filesystem::copy_file(kDataScene.parent_path() / "luminaires/lambertian-panel.ldt",
                             dir.path() / "panel.ldt");
  const Scene scene = parseScene(sceneWith("  - {name: p, file: point.ies, position: [0, 0, 3]}\n"
                                           "  - {name: q, file: panel.ldt, position: [1, 0, 3]}\n"
                                           "  - {name: r, file: panel.ldt, position: [2, 0, 3], "
                                           "model: point}\n"),
                                 dir.path() / "scene.yaml");
  ASSERT_EQ(scene.luminaires.size(), 3u);
  EXPECT_EQ(scene.luminaires[0].model, LuminaireModel::Point);
  EXPECT_FALSE(scene.luminaires[0].opening.has_value());
  EXPECT_EQ(scene.luminaires[1].model, LuminaireModel::Area);
  EXPECT_TRUE(scene.luminaires[1].opening.has_value());
  EXPECT_EQ(scene.luminaires[2].model, LuminaireModel::Point);
}

TEST(LuminaireScene, ArraysNeedWholeCountsAndPositiveSpacings) {
  expectError(
      "  - {name: d, file: luminaires/narrow-downlight.ies, position: [0, 0, 3], "
      "array: {count: [2.5, 1], spacing: [1, 1]}}\n",
      4, "luminaires[0].array.count", "whole numbers");
  expectError(
      "  - {name: d, file: luminaires/narrow-downlight.ies, position: [0, 0, 3], "
      "array: {count: [2, 1], spacing: [0, 1]}}\n",
      4, "luminaires[0].array.spacing", "greater than 0");
}

TEST(LuminaireScene, NamesAreUnique) {
  expectError(
      "  - {name: d, file: luminaires/narrow-downlight.ies, position: [0, 0, 3]}\n"
      "  - {name: d, file: luminaires/batwing.ldt, position: [1, 0, 3]}\n",
      5, "luminaires[1]", "already used");
}

}  // namespace
}  // namespace penumbra
