// Scene parameters: `parameters:` with defaults, "${expression}" in numeric fields, values given
// from outside (a sweep, `grid --set`), and errors that name the file, line, key and expression.
#include <cmath>
#include <filesystem>
#include <functional>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "scene/parameters.hpp"
#include "scene/scene_loader.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

const fs::path kOffice = fs::path(PENUMBRA_SOURCE_DIR) / "data" / "office.yaml";

// A 4 × 3 × 3 m room whose window, panel and grid follow two parameters.
constexpr const char* kScene = R"(penumbra: 1
parameters: {w: 1.0, flux: 3000}
materials: {floor: "${0.1 * 2}"}
room:
  size: ["${2 + 2}", 3, 3]
  materials: {floor: floor}
  openings:
    - {name: window, wall: y0, x: "${2 - w/2}", z: 1, width: "${w}", height: 1}
sources:
  - {name: sky, opening: window, luminance: 1000}
  - {name: "${flux}", rect: {center: [2, 1.5, 2.99], size: [0.5, 0.5], normal: [0, 0, -1]}, flux: "${flux}"}
grids:
  - {name: floor, height: 0, spacing: "${w / 2}", margin: 0.5}
)";

// The SceneError `load` throws; fails the test when it throws none.
SceneError sceneError(const std::function<void()>& load) {
  try {
    load();
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a SceneError";
  return SceneError("none", -1, "", "none");
}

SceneError errorIn(const std::string& yaml, const ParameterValues& values = {}) {
  return sceneError([&] { parseScene(yaml, "test.yaml", values); });
}

// kScene with `from` replaced by `to` (once).
std::string sceneWith(const std::string& from, const std::string& to) {
  std::string text = kScene;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

void expectContains(const std::string& text, const std::string& words) {
  EXPECT_NE(text.find(words), std::string::npos) << text;
}

double xMin(const ConvexPolygon& polygon) {
  double x = polygon.vertices().front().x();
  for (const Vec3& v : polygon.vertices()) x = std::min(x, v.x());
  return x;
}

TEST(Parameters, DefaultsApplyWhenTheSceneLoadsAlone) {
  const Scene scene = parseScene(kScene, "test.yaml");
  EXPECT_EQ(scene.parameters, (ParameterValues{{"w", 1.0}, {"flux", 3000.0}}));
  EXPECT_EQ(scene.room->size, Vec3(4, 3, 3));
  EXPECT_EQ(scene.materials[0].reflectance, Vec3::Constant(0.2));
  EXPECT_DOUBLE_EQ(xMin(scene.room->openings[0].inner), 1.5);
  EXPECT_NEAR(scene.sources[0].emittingArea(), 1.0, 1e-12);
  EXPECT_NEAR(scene.sources[1].luminance, 3000.0 / (std::numbers::pi * 0.25), 1e-9);
  EXPECT_DOUBLE_EQ(scene.grids[0].spacing, 0.5);
  // Text is never evaluated: a name stays what it says.
  EXPECT_EQ(scene.sources[1].name, "${flux}");
}

TEST(Parameters, GivenValuesReplaceDefaultsByName) {
  const Scene scene = parseScene(kScene, "test.yaml", {{"flux", 4000.0}, {"w", 2.0}});
  EXPECT_EQ(scene.parameters, (ParameterValues{{"w", 2.0}, {"flux", 4000.0}}));
  EXPECT_DOUBLE_EQ(xMin(scene.room->openings[0].inner), 1.0);
  EXPECT_NEAR(scene.sources[0].emittingArea(), 2.0, 1e-12);
  EXPECT_NEAR(scene.sources[1].luminance, 4000.0 / (std::numbers::pi * 0.25), 1e-9);
  EXPECT_DOUBLE_EQ(scene.grids[0].spacing, 1.0);
}

TEST(Parameters, AnExpressionCannotChangeAParameterForLaterFields) {
  // muparser's '=' assigns; each field starts again from the given values.
  const Scene scene =
      parseScene(sceneWith(R"(size: ["${2 + 2}", 3, 3])", R"(size: ["${w = 5}", "${w + 2}", 3])"),
                 "test.yaml");
  EXPECT_EQ(scene.room->size, Vec3(5, 3, 3));
}

TEST(Parameters, ExpressionsWorkWithoutParametersToo) {
  const Scene scene = parseScene(
      "penumbra: 1\nroom: {size: [\"${2 * _pi}\", \"${sqrt(16)}\", \"${max(2, 3)}\"]}\n", "t.yaml");
  EXPECT_DOUBLE_EQ(scene.room->size.x(), 2 * std::numbers::pi);
  EXPECT_EQ(scene.room->size.y(), 4.0);
  EXPECT_EQ(scene.room->size.z(), 3.0);
}

TEST(Parameters, TheOfficeKeepsItsGeometryWithItsDefaults) {
  const Scene scene = loadScene(kOffice);
  ASSERT_EQ(scene.parameters.size(), 5u);
  EXPECT_EQ(scene.parameters[0], (ParameterValue{"window_width_m", 2.0}));
  EXPECT_DOUBLE_EQ(xMin(scene.room->openings[0].inner), 2.0);
  EXPECT_NEAR(scene.sources[0].emittingArea(), 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(scene.sources[1].faces[0].centroid().x(), 1.5);
  EXPECT_DOUBLE_EQ(scene.sources[2].faces[0].centroid().x(), 4.5);
  EXPECT_NEAR(scene.sources[1].luminance, 3400.0 / (std::numbers::pi * 0.36), 1e-9);
}

TEST(Parameters, TheOfficeWindowStaysCentred) {
  const Scene scene = loadScene(kOffice, {{"window_width_m", 1.2}, {"panel_spacing_m", 2.0}});
  EXPECT_DOUBLE_EQ(xMin(scene.room->openings[0].inner), 2.4);
  EXPECT_NEAR(scene.sources[0].emittingArea(), 1.2 * 1.5, 1e-12);
  EXPECT_DOUBLE_EQ(scene.sources[1].faces[0].centroid().x(), 2.0);
  EXPECT_EQ(loadSceneParameters(kOffice).size(), 5u);
}

// ---------------------------------------------------------------- errors

TEST(ParameterErrors, AnUnknownNameInAnExpression) {
  const SceneError e = errorIn(sceneWith(R"(x: "${2 - w/2}")", R"(x: "${2 - wdth/2}")"));
  EXPECT_EQ(e.line(), 8);
  EXPECT_EQ(e.key(), "room.openings[0].x");
  expectContains(e.what(), "test.yaml:8: room.openings[0].x: cannot evaluate ${2 - wdth/2}");
  expectContains(e.what(), "wdth");
  expectContains(e.what(), "the scene's parameters: w, flux");
}

TEST(ParameterErrors, ASyntaxError) {
  const SceneError e = errorIn(sceneWith(R"(height: 0,)", R"(height: "${1 +}",)"));
  EXPECT_EQ(e.key(), "grids[0].height");
  expectContains(e.what(), "cannot evaluate ${1 +}");
}

TEST(ParameterErrors, ANumberThatIsNotFinite) {
  const SceneError e = errorIn(sceneWith(R"(spacing: "${w / 2}")", R"(spacing: "${w / 0}")"));
  EXPECT_EQ(e.key(), "grids[0].spacing");
  expectContains(e.what(), "${w / 0} gives inf, not a finite number (with w = 1)");
}

TEST(ParameterErrors, AnInvalidValueShowsTheExpressionsBehindIt) {
  // A window wider than the wall: the opening is wrong, and its x and width came from w.
  const SceneError e = errorIn(kScene, {{"w", 7.0}});
  EXPECT_EQ(e.line(), 8);
  EXPECT_EQ(e.key(), "room.openings[0]");
  expectContains(e.what(), "does not fit");
  expectContains(e.what(), "room.openings[0].x = ${2 - w/2} = -1.5");
  expectContains(e.what(), "room.openings[0].width = ${w} = 7");
  expectContains(e.what(), "with w = 7)");
}

TEST(ParameterErrors, ARangeErrorOnAnEvaluatedField) {
  const SceneError e = errorIn(kScene, {{"flux", -5.0}});
  EXPECT_EQ(e.key(), "sources[1].flux");
  expectContains(e.what(),
                 "must not be negative (got -5 lm) (sources[1].flux = ${flux} = -5; "
                 "with flux = -5)");
}

TEST(ParameterErrors, AnUndeclaredValueFromOutside) {
  const SceneError e = errorIn(kScene, {{"width", 2.0}});
  EXPECT_EQ(e.line(), 2);
  EXPECT_EQ(e.key(), "parameters");
  expectContains(e.what(), "'width' is not a parameter of this scene; it declares: w, flux");
  const SceneError none = errorIn("penumbra: 1\n", {{"width", 2.0}});
  expectContains(none.what(), "it declares none");
}

TEST(ParameterErrors, NamesAndDefaults) {
  SceneError e = errorIn("penumbra: 1\nparameters: {1w: 2}\n");
  EXPECT_EQ(e.key(), "parameters.1w");
  expectContains(e.what(), "cannot be a parameter name");
  e = errorIn("penumbra: 1\nparameters: {w: \"${2}\"}\n");
  EXPECT_EQ(e.key(), "parameters.w");
  expectContains(e.what(), "parameter defaults and study files take plain numbers");
  e = errorIn("penumbra: 1\nparameters: [1, 2]\n");
  EXPECT_EQ(e.key(), "parameters");
  e = errorIn("penumbra: 1\nparameters: {w: 1, w: 2}\n");
  expectContains(e.what(), "appears twice");
}

// ---------------------------------------------------------------- small parts

TEST(ParameterText, Assignments) {
  EXPECT_EQ(parseParameterAssignment("window_width_m=1.6"),
            (ParameterValue{"window_width_m", 1.6}));
  EXPECT_EQ(parseParameterAssignment("_a=-2e3"), (ParameterValue{"_a", -2000.0}));
  for (const char* bad : {"w", "w=", "=2", "1w=2", "w=2x", "w=inf", "w-x=2"}) {
    EXPECT_THROW(parseParameterAssignment(bad), std::invalid_argument) << bad;
  }
}

TEST(ParameterText, ExpressionsAreDollarBraces) {
  EXPECT_EQ(scenefile::expressionText(" ${a + 1} "), "a + 1");
  EXPECT_EQ(scenefile::expressionText("${}"), "");  // an empty expression: an error when evaluated
  EXPECT_EQ(scenefile::expressionText("$a"), std::nullopt);
  EXPECT_EQ(scenefile::expressionText("a ${b}"), std::nullopt);
  EXPECT_EQ(describeParameters({{"a", 1.5}, {"b", 3000}}), "a = 1.5, b = 3000");
}

}  // namespace
}  // namespace penumbra
