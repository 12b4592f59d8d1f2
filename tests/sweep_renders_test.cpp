// Renders per case of a sweep (`renders: [view]` in a study): the case folders hold the views,
// and a reflectance sweep changes the image by exactly the reflectance, not the illuminance.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "output/image_files.hpp"
#include "scene/scene_loader.hpp"
#include "study/case_renders.hpp"
#include "study/study_reader.hpp"
#include "study/sweep_runner.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using testing::readText;
using testing::TempDir;

constexpr const char* kScene = R"(penumbra: 1
parameters: {floor_reflectance: 0.2}
materials: {carpet: "${floor_reflectance}", paint: 0.7}
room: {size: [3, 3, 2.5], materials: {floor: carpet, walls: paint, ceiling: paint}}
solids:
  - {name: table, box: {min: [1, 1, 0.7], max: [2, 2, 0.75]}, material: paint}
sources:
  - {name: panel, rect: {center: [1.5, 1.5, 2.49], size: [0.6, 0.6], normal: [0, 0, -1]}, flux: 3000}
grids:
  - {name: floor, height: 0, spacing: 0.5, margin: 0.25}
views:
  - {name: corner, eye: [2.8, 2.8, 1.6], target: [1.2, 1.2, 0.2], fov: 80, size: [48, 32]}
)";

constexpr const char* kStudy = R"(penumbra-study: 1
scene: scene.yaml
parameters:
  floor_reflectance: [0.2, 0.6]
renders: [corner]
)";

void write(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

TEST(SweepRenders, EachCaseRendersItsViewsAndDirectOnlyReflectanceScalesOnlyTheLuminance) {
  TempDir dir("penumbra-sweep-renders");
  write(dir.path() / "scene.yaml", kScene);
  write(dir.path() / "study.yaml", kStudy);
  const Study study = loadStudy(dir.path() / "study.yaml");
  ASSERT_EQ(study.renders, std::vector<std::string>{"corner"});
  SweepSettings settings;
  settings.output = dir.path() / "out";
  settings.estimator.device = "cpu";
  settings.estimator.interreflection = false;  // direct light: E does not depend on ρ
  settings.version = "test";
  settings.caseOutputs = {std::make_shared<CaseRenders>(study.renders, settings.estimator)};
  SweepObserver silent;
  const SweepSummary summary = runSweep(study, settings, silent);
  EXPECT_TRUE(summary.outputNotes.empty());
  const fs::path dark = dir.path() / "out/cases/case-001",
                 light = dir.path() / "out/cases/case-002";
  for (const char* name : {"corner.exr", "corner.E.exr", "corner.faceid.exr", "corner.png"}) {
    EXPECT_TRUE(fs::exists(dark / name)) << name;
    EXPECT_TRUE(fs::exists(light / name)) << name;
  }
  const auto rows = testing::lines(readText(dir.path() / "out/results.csv"));
  EXPECT_TRUE(rows[0].ends_with(",corner_png")) << rows[0];
  EXPECT_TRUE(rows[1].ends_with(",cases/case-001/corner.png")) << rows[1];

  // The room's floor slab is solid 0: its faces have ids 1-6. E is the same in both cases; the
  // floor's luminance triples with its reflectance (0.2 → 0.6); everything else stays.
  const ScalarImage e1 = readScalarExr(dark / "corner.E.exr"),
                    e2 = readScalarExr(light / "corner.E.exr");
  const RgbImage l1 = readRgbExr(dark / "corner.exr"), l2 = readRgbExr(light / "corner.exr");
  const FaceIdImage faces = readFaceIdExr(dark / "corner.faceid.exr");
  EXPECT_EQ(e1.values, e2.values);
  int floorPixels = 0, otherPixels = 0;
  for (int y = 0; y < faces.height; ++y)
    for (int x = 0; x < faces.width; ++x) {
      const uint32_t id = faces.at(x, y);
      if (id >= 1 && id <= 6 && e1.at(x, y) > 0.0f) {
        ++floorPixels;
        EXPECT_NEAR(l2.pixel(x, y)[1], 3.0 * l1.pixel(x, y)[1], 1e-5 * l2.pixel(x, y)[1]);
      } else if (id > 6) {
        ++otherPixels;
        EXPECT_EQ(l2.pixel(x, y)[1], l1.pixel(x, y)[1]);
      }
    }
  EXPECT_GT(floorPixels, 48 * 32 / 8);
  EXPECT_GT(otherPixels, 48 * 32 / 8);
}

// The renders follow the sweep's light: with interreflection (the default) a brighter floor
// lights the rest of the room too, so E rises on faces that are not the floor, and the case's
// render.json says what the images include.
TEST(SweepRenders, WithInterreflectionTheFloorsReflectanceLightsTheRoom) {
  TempDir dir("penumbra-sweep-renders");
  write(dir.path() / "scene.yaml", kScene);
  write(dir.path() / "study.yaml", kStudy);
  const Study study = loadStudy(dir.path() / "study.yaml");
  SweepSettings settings;
  settings.output = dir.path() / "out";
  settings.estimator.device = "cpu";
  settings.version = "test";
  settings.caseOutputs = {std::make_shared<CaseRenders>(study.renders, settings.estimator)};
  SweepObserver silent;
  runSweep(study, settings, silent);
  const fs::path dark = dir.path() / "out/cases/case-001",
                 light = dir.path() / "out/cases/case-002";
  EXPECT_NE(readText(light / "render.json").find(R"x("light": "total (direct + interreflected)")x"),
            std::string::npos);
  const ScalarImage e1 = readScalarExr(dark / "corner.E.exr"),
                    e2 = readScalarExr(light / "corner.E.exr");
  const FaceIdImage faces = readFaceIdExr(dark / "corner.faceid.exr");
  int brighter = 0, others = 0;
  for (int y = 0; y < faces.height; ++y)
    for (int x = 0; x < faces.width; ++x) {
      const uint32_t id = faces.at(x, y);
      if (id <= 6 || e1.at(x, y) <= 0.0f) continue;  // nothing, the floor, or the panel
      ++others;
      brighter += e2.at(x, y) > e1.at(x, y);
    }
  EXPECT_GT(others, 48 * 32 / 8);
  EXPECT_EQ(brighter, others);
}

TEST(SweepRenders, AnUnknownViewIsAnErrorNamingTheScenesViews) {
  TempDir dir("penumbra-sweep-renders");
  write(dir.path() / "scene.yaml", kScene);
  write(dir.path() / "study.yaml",
        std::string(kStudy).replace(std::string(kStudy).find("[corner]"), 8, "[door]"));
  try {
    loadStudy(dir.path() / "study.yaml");
    ADD_FAILURE() << "expected an error";
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 5);
    EXPECT_NE(std::string(e.what()).find("no view 'door'; its views are: corner"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace penumbra
