// Views and observers in scene files (the eyes of `render` and `glare`): what is read, the
// defaults, grids of observers, and one test per error, each with the line and key a lighting
// designer is sent to.
#include <gtest/gtest.h>

#include <string>

#include "scene/scene_loader.hpp"

namespace penumbra {
namespace {

const std::string kRoom = R"(penumbra: 1
room: {size: [4, 3, 2.8]}
solids:
  - {name: desk, box: {min: [1, 1, 0.7], max: [2, 2, 0.75]}}
)";

SceneError errorOf(const std::string& views) {
  try {
    parseScene(kRoom + views, "test.yaml");
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a SceneError for:\n" << views;
  return SceneError("test.yaml", -1, "", "none");
}

void expectError(const std::string& views, int line, const std::string& key,
                 const std::string& words) {
  const SceneError e = errorOf(views);
  EXPECT_EQ(e.line(), line) << e.what();
  EXPECT_EQ(e.key(), key) << e.what();
  EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
}

TEST(Views, AreReadWithTheirDefaults) {
  const Scene scene = parseScene(kRoom + R"(views:
  - {name: door, eye: [3.5, 2.5, 1.6], target: [0, 0, 1]}
  - {name: plan, eye: [2, 1.5, 2.7], target: [2, 1.5, 0], up: [0, 1, 0], fov: 100, size: [320, 240]}
)",
                                 "test.yaml");
  ASSERT_EQ(scene.views.size(), 2u);
  const View& door = scene.views[0];
  EXPECT_EQ(door.name, "door");
  EXPECT_EQ(door.eye, Vec3(3.5, 2.5, 1.6));
  EXPECT_EQ(door.up, Vec3::UnitZ());
  EXPECT_EQ(door.fovDegrees, 60.0);
  EXPECT_EQ(door.width, 1280);
  EXPECT_EQ(door.height, 720);
  const View& plan = scene.views[1];
  EXPECT_EQ(plan.up, Vec3::UnitY());
  EXPECT_EQ(plan.fovDegrees, 100.0);
  EXPECT_EQ(plan.width, 320);
  EXPECT_EQ(plan.height, 240);
}

TEST(Views, TheOfficeHasTheViewsTheReadmeRenders) {
  const Scene scene = loadScene(PENUMBRA_SOURCE_DIR "/data/office.yaml");
  ASSERT_GE(scene.views.size(), 1u);
  EXPECT_EQ(scene.views.front().name, "from-door");
}

TEST(Views, Errors) {
  expectError("views:\n  - {name: a, eye: [1, 1, 1], target: [1, 1, 1]}\n", 6, "views[0].target",
              "must differ from the eye");
  expectError("views:\n  - {name: a, eye: [1, 1, 2], target: [1, 1, 0]}\n", 6, "views[0].target",
              "give 'up'");
  expectError("views:\n  - {name: a, eye: [1, 1, 2], target: [2, 1, 2], up: [1, 0, 0]}\n", 6,
              "views[0].up", "along the line of sight");
  expectError("views:\n  - {name: a, eye: [1, 1, 2], target: [2, 1, 2], fov: 180}\n", 6,
              "views[0].fov", "at most 170");
  expectError("views:\n  - {name: a, eye: [1, 1, 2], target: [2, 1, 2], fov: 0}\n", 6,
              "views[0].fov", "greater than 0");
  expectError("views:\n  - {name: a, eye: [1, 1, 2], target: [2, 1, 2], size: [640.5, 480]}\n", 6,
              "views[0].size[0]", "whole number of pixels");
  expectError("views:\n  - {name: a, eye: [1, 1, 2], target: [2, 1, 2], size: [640]}\n", 6,
              "views[0].size", "[width, height]");
  expectError("views:\n  - {name: a, eye: [1, 1, 2], target: [2, 1, 2], zoom: 2}\n", 6,
              "views[0].zoom", "zoom");
  expectError("views:\n  - {name: a, target: [2, 1, 2]}\n", 6, "views[0].eye", "eye");
  // The eye inside the desk: the view would show the inside of a solid.
  expectError("views:\n  - {name: a, eye: [1.5, 1.5, 0.72], target: [2, 1, 2]}\n", 6,
              "views[0].eye", "inside the solid 'desk'");
  expectError(
      "views:\n  - {name: a, eye: [1, 1, 2], target: [2, 1, 2]}\n  - {name: a, eye: [1, 1, 2], "
      "target: [2, 1, 1]}\n",
      7, "views[1]", "already used");
}

TEST(Observers, AreReadWithTheFourAxisDirectionsByDefault) {
  const Scene scene = parseScene(kRoom + R"(observers:
  - {name: desk-1, eye: [2.0, 1.5, 1.2], look: [2, 0, 0]}
  - {name: door, eye: [3.5, 2.5, 1.6]}
)",
                                 "test.yaml");
  ASSERT_EQ(scene.observers.size(), 2u);
  EXPECT_EQ(scene.observers[0].name, "desk-1");
  EXPECT_EQ(scene.observers[0].entry, "desk-1");
  EXPECT_EQ(scene.observers[0].eye, Vec3(2.0, 1.5, 1.2));
  ASSERT_EQ(scene.observers[0].looks.size(), 1u);
  EXPECT_EQ(scene.observers[0].looks[0], Vec3::UnitX());  // unit
  const std::vector<Vec3> axes{Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitX(), -Vec3::UnitY()};
  EXPECT_EQ(scene.observers[1].looks, axes);
}

TEST(Observers, AGridIsOneEyePerCellCentre) {
  const Scene scene = parseScene(kRoom + R"(observers:
  - {name: row, grid: {origin: [0.5, 0.5, 1.2], u: [3, 0, 0], v: [0, 2, 0], spacing: 1.0}, look: [1, 0, 0]}
)",
                                 "test.yaml");
  // 3 m / 1 m = 3 columns, 2 m / 1 m = 2 rows; centres at origin + (i + ½)·u/3 + (j + ½)·v/2.
  ASSERT_EQ(scene.observers.size(), 6u);
  EXPECT_EQ(scene.observers[0].name, "row[1,1]");
  EXPECT_EQ(scene.observers[0].entry, "row");
  EXPECT_TRUE(scene.observers[0].eye.isApprox(Vec3(1.0, 1.0, 1.2), 1e-12));
  EXPECT_EQ(scene.observers[5].name, "row[3,2]");
  EXPECT_TRUE(scene.observers[5].eye.isApprox(Vec3(3.0, 2.0, 1.2), 1e-12));
  EXPECT_EQ(scene.observers[5].looks.size(), 1u);
}

TEST(Observers, BadObserversNameTheLineAndKey) {
  expectError("observers:\n  - {name: a, eye: [1.5, 1.5, 0.72]}\n", 6, "observers[0].eye",
              "observer 'a': the eye [1.5, 1.5, 0.72] m is inside the solid 'desk'");
  expectError("observers:\n  - {name: a, eye: [1, 1, 1.2], look: [0, 0, 0]}\n", 6,
              "observers[0].look", "zero vector");
  expectError("observers:\n  - {name: a, eye: [1, 1, 1.2], look: [0, 0, -1]}\n", 6,
              "observers[0].look", "straight up or down");
  expectError("observers:\n  - {name: a}\n", 6, "observers[0]", "needs 'eye");
  expectError(
      "observers:\n  - {name: a, eye: [1, 1, 1], grid: {origin: [0, 0, 1], u: [1, 0, 0], v: [0, "
      "1, 0], spacing: 1}}\n",
      6, "observers[0].grid", "not both");
  expectError(
      "observers:\n  - {name: a, grid: {origin: [0, 0, 1], u: [1, 0, 0], v: [2, 0, 0], spacing: "
      "1}}\n",
      6, "observers[0].grid.v", "span no area");
  expectError(
      "observers:\n  - {name: a, grid: {origin: [1.1, 1.1, 0.72], u: [0.5, 0, 0], v: [0, 0.5, 0], "
      "spacing: 0.25}}\n",
      6, "observers[0].grid", "is inside the solid 'desk'");
  expectError("observers:\n  - {name: a, eye: [1, 1, 1]}\n  - {name: a, eye: [2, 1, 1]}\n", 7,
              "observers[1]", "already used");
  expectError("observers:\n  - {name: a, eye: [1, 1, 1], target: [1, 1, 1]}\n", 6,
              "observers[0].target", "");
}

}  // namespace
}  // namespace penumbra
