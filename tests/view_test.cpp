// Views in scene files: what is read, the defaults, and one test per
// error, each with the line and key a lighting designer is sent to.
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

}  // namespace
}  // namespace penumbra
