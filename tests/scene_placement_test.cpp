// Modelling mistakes that would otherwise pass silently: a source inside a solid (an error at its
// line and key), a source that lights nothing and a rectangle grid outside the room or facing
// away from every source (a warning each, naming them). Valid scenes get no warning.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "scene/scene_loader.hpp"
#include "study/study_cases.hpp"
#include "study/study_reader.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

const fs::path kSourceDir = PENUMBRA_SOURCE_DIR;

// A 6 × 4 × 2.8 m classroom with 0.2 m slabs (the ceiling slab spans z 2.8 to 3.0 m), a window in
// wall y0, a desk and a desk-top grid. Line 10 holds the one source, line 13 the extra grid.
std::string classroom(const std::string& source, const std::string& grid = "") {
  return "penumbra: 1\n"                                                              // 1
         "room:\n"                                                                    // 2
         "  size: [6.0, 4.0, 2.8]\n"                                                  // 3
         "  wall_thickness: 0.2\n"                                                    // 4
         "  openings:\n"                                                              // 5
         "    - {name: window, wall: y0, x: 2.0, z: 0.9, width: 2.0, height: 1.5}\n"  // 6
         "solids:\n"                                                                  // 7
         "  - {name: desk, box: {min: [1, 1.5, 0.72], max: [2.6, 2.3, 0.75]}}\n"      // 8
         "sources:\n"                                                                 // 9
         "  - " +
         source +
         "\n"                                           // 10
         "grids:\n"                                     // 11
         "  - {name: work-plane, height: 0.8}\n"        // 12
         + (grid.empty() ? "" : "  - " + grid + "\n");  // 13
}

std::string panel(const std::string& center, const std::string& normal = "[0, 0, -1]") {
  return "{name: panel, rect: {center: " + center + ", size: [0.6, 0.6], normal: " + normal +
         "}, flux: 3400}";
}

const char* kDownlight =
    "{name: panel, rect: {center: [3, 2, 2.8], size: [0.6, 0.6], normal: "
    "[0, 0, -1]}, flux: 3400}";

SceneError errorOf(const std::string& yaml) {
  try {
    parseScene(yaml, "test.yaml");
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a SceneError for:\n" << yaml;
  return SceneError("test.yaml", -1, "", "none");
}

bool contains(const std::string& text, const std::string& words) {
  return text.find(words) != std::string::npos;
}

// The scene's one warning, as printed; fails the test unless there is exactly one.
std::string onlyWarning(const std::string& yaml) {
  const Scene scene = parseScene(yaml, "test.yaml");
  EXPECT_EQ(scene.warnings.size(), 1u);
  if (scene.warnings.size() != 1u) return "";
  return warningText(scene.file, scene.warnings.front());
}

// ---------------------------------------------------------------- sources inside solids

TEST(SourcePlacement, APanelInsideTheCeilingSlabIsAnErrorNamingTheSlab) {
  const SceneError e = errorOf(classroom(panel("[3, 2, 2.95]")));
  EXPECT_EQ(e.line(), 10) << e.what();
  EXPECT_EQ(e.key(), "sources[0].rect") << e.what();
  EXPECT_TRUE(contains(e.what(), "source 'panel' lies inside the solid 'room.ceiling'"))
      << e.what();
  EXPECT_TRUE(contains(e.what(), "z 2.95 m")) << e.what();
}

TEST(SourcePlacement, ASourceWhollyInsideAnySolidIsAnError) {
  // A vertical panel inside the desk top, and a little box lamp inside a wall.
  const SceneError desk =
      errorOf(classroom("{name: lamp, polygon: [[1.2, 1.6, 0.73], [1.4, 1.6, 0.73], [1.4, 1.6, "
                        "0.74]], luminance: 100}"));
  EXPECT_EQ(desk.key(), "sources[0].polygon") << desk.what();
  EXPECT_TRUE(contains(desk.what(), "inside the solid 'desk'")) << desk.what();
  const SceneError wall =
      errorOf(classroom("{name: lamp, box: {min: [-0.15, 1, 1], max: [-0.05, 1.1, 1.1]}, "
                        "luminance: 100}"));
  EXPECT_EQ(wall.key(), "sources[0].box") << wall.what();
  EXPECT_TRUE(contains(wall.what(), "inside the solid 'room.wall-x0'")) << wall.what();
}

TEST(SourcePlacement, AFlushPanelOnTheCeilingIsNoError) {
  const Scene scene = parseScene(classroom(kDownlight), "test.yaml");
  EXPECT_TRUE(scene.warnings.empty());
}

// ---------------------------------------------------------------- sources that light nothing

TEST(SourcePlacement, APanelAboveTheCeilingLightsNothing) {
  const std::string w = onlyWarning(classroom(panel("[3, 2, 3.5]")));
  EXPECT_TRUE(contains(w, "test.yaml:10: warning: sources[0]: source 'panel' lights nothing")) << w;
  EXPECT_TRUE(contains(w, "outside the room (x 2.7 to 3.3, y 1.7 to 2.3, z 3.5 m")) << w;
}

TEST(SourcePlacement, APanelOutsideTheRoomLightsNothing) {
  const std::string w = onlyWarning(classroom(panel("[9, 2, 2.7]")));
  EXPECT_TRUE(contains(w, "source 'panel' lights nothing: it lies outside the room")) << w;
}

TEST(SourcePlacement, APanelFacingTheCeilingItIsFlushWithLightsNothing) {
  const std::string w = onlyWarning(classroom(panel("[3, 2, 2.8]", "[0, 0, 1]")));
  EXPECT_TRUE(contains(w,
                       "test.yaml:10: warning: sources[0]: source 'panel' lights nothing: "
                       "it emits towards [0, 0, 1]"))
      << w;
}

TEST(SourcePlacement, AnUplightBelowTheCeilingLightsTheCeiling) {
  const Scene scene = parseScene(classroom(panel("[3, 2, 2.5]", "[0, 0, 1]")), "test.yaml");
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(SourcePlacement, ASkyOutsideTheWindowShinesThroughIt) {
  // Outside the room, 1 m in front of the window and facing it.
  const Scene scene =
      parseScene(classroom("{name: sky, polygon: [[2, -1.2, 0.9], [4, -1.2, 0.9], [4, -1.2, 2.4], "
                           "[2, -1.2, 2.4]], normal: [0, 1, 0], luminance: 4000}"),
                 "test.yaml");
  EXPECT_TRUE(scene.warnings.empty());
  // The same sky facing away from the window lights nothing.
  const std::string w = onlyWarning(
      classroom("{name: sky, polygon: [[2, -1.2, 0.9], [4, -1.2, 0.9], [4, -1.2, 2.4], [2, -1.2, "
                "2.4]], normal: [0, -1, 0], luminance: 4000}"));
  EXPECT_TRUE(contains(w, "source 'sky' lights nothing: it lies outside the room")) << w;
}

// ---------------------------------------------------------------- rectangle grids

TEST(GridPlacement, AGridOutsideTheRoomIsNamedWithWhy) {
  const std::string w = onlyWarning(
      classroom(kDownlight,
                "{name: desk-top, rect: {origin: [-2, 1, 0.75], u: [1.4, 0, 0], v: [0, 0.6, 0]}}"));
  EXPECT_TRUE(contains(w,
                       "test.yaml:13: warning: grids[1]: grid 'desk-top' lies outside the room "
                       "(it spans x -2 to -0.6, y 1 to 1.6, z 0.75 m; the room's interior "
                       "spans x 0 to 6, y 0 to 4, z 0 to 2.8 m)"))
      << w;
}

TEST(GridPlacement, AGridWithUAndVSwappedFacesAwayFromEverySource) {
  const std::string w = onlyWarning(classroom(
      kDownlight,
      "{name: desk-top, rect: {origin: [1, 1.5, 0.75], u: [0, 0.8, 0], v: [1.6, 0, 0]}}"));
  EXPECT_TRUE(contains(w,
                       "grids[1]: grid 'desk-top' faces away from every source: its normal u × "
                       "v is [0, 0, -1]"))
      << w;
}

TEST(GridPlacement, AGridInsideAWallIsReportedByItsPointsNotWarned) {
  // Its points lie inside the wall: the run reports them as inside solids (E = 0).
  const Scene scene = parseScene(
      classroom(kDownlight,
                "{name: in-wall, rect: {origin: [-0.1, 1, 0.5], u: [0, 1, 0], v: [0, 0, 1]}}"),
      "test.yaml");
  EXPECT_TRUE(scene.warnings.empty());
}

TEST(GridPlacement, AGridOnTheFloorFacingUpIsFine) {
  const Scene scene = parseScene(
      classroom(kDownlight, "{name: floor, rect: {origin: [0, 0, 0], u: [6, 0, 0], v: [0, 4, 0]}}"),
      "test.yaml");
  EXPECT_TRUE(scene.warnings.empty());
}

// ---------------------------------------------------------------- valid scenes

TEST(ScenePlacement, TheExampleScenesGetNoWarning) {
  for (const char* name : {"office.yaml", "open-office.yaml"}) {
    const Scene scene = loadScene(kSourceDir / "data" / name);
    EXPECT_TRUE(scene.warnings.empty())
        << name << ": " << warningText(scene.file, scene.warnings.front());
  }
}

TEST(ScenePlacement, EveryCaseOfTheExampleStudiesGetsNoWarning) {
  int cases = 0;
  for (const auto& entry : fs::directory_iterator(kSourceDir / "studies")) {
    if (entry.path().extension() != ".yaml") continue;
    const Study study = loadStudy(entry.path());
    for (const StudyCase& c : studyCases(study)) {
      const Scene scene = loadScene(study.scene, c.values);
      EXPECT_TRUE(scene.warnings.empty())
          << entry.path() << " " << c.id << ": " << warningText(scene.file, scene.warnings.front());
      ++cases;
    }
  }
  EXPECT_GT(cases, 0);
}

}  // namespace
}  // namespace penumbra
