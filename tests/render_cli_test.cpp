// `penumbra render` as a user runs it: the files, their headers and units, and errors that write
// nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <numbers>

#include "output/image_files.hpp"
#include "penumbra_process.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;
namespace fs = std::filesystem;

// A floor, a table and a panel; one view from a corner.
const char* kScene = R"(penumbra: 1
materials: {grey: 0.5}
solids:
  - {name: floor, box: {min: [0, 0, -0.1], max: [4, 4, 0]}, material: grey}
  - {name: table, box: {min: [1, 1, 0.7], max: [2, 2, 0.75]}}
sources:
  - {name: panel, rect: {center: [1.5, 1.5, 2.5], size: [0.6, 0.6], normal: [0, 0, -1]}, luminance: 3000}
views:
  - {name: corner, eye: [3.8, 3.8, 1.6], target: [1.5, 1.5, 0.3], fov: 70, size: [64, 48]}
  - {name: top, eye: [2, 2, 3.5], target: [2, 2, 0], up: [0, 1, 0], fov: 60, size: [32, 32]}
)";

void writeScene(const fs::path& dir) {
  std::ofstream(dir / "scene.yaml") << kScene;
}

std::string metadataValue(const fs::path& file, const std::string& name) {
  for (const auto& [key, value] : readImageMetadata(file))
    if (key == name) return value;
  return "";
}

TEST(RenderCli, WritesEveryFileWithViewAndUnitsInTheHeaders) {
  TempDir dir("penumbra-render-cli");
  writeScene(dir.path());
  const Result r = runPenumbra(dir.path(), "render scene.yaml --view corner -o out --interval 2");
  if (r.status == 1 && r.err.find("device") != std::string::npos)
    GTEST_SKIP() << "no OpenCL device: " << r.err;
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path out = dir.path() / "out";
  for (const char* name : {"corner.exr", "corner.hdr", "corner.E.exr", "corner.faceid.exr",
                           "corner.png", "render.json"})
    EXPECT_TRUE(fs::exists(out / name)) << name;
  EXPECT_FALSE(fs::exists(out / "top.exr")) << "only the view asked for";
  EXPECT_EQ(metadataValue(out / "corner.exr", "penumbra:view"), "corner");
  EXPECT_EQ(metadataValue(out / "corner.exr", "penumbra:units"), "cd/m2");
  EXPECT_EQ(metadataValue(out / "corner.E.exr", "penumbra:units"), "lx");
  EXPECT_EQ(metadataValue(out / "corner.exr", "penumbra:scene"), "scene.yaml");

  // L = ρ·E/π on the grey floor, pixel by pixel, between the two files.
  const RgbImage luminance = readRgbExr(out / "corner.exr");
  const ScalarImage e = readScalarExr(out / "corner.E.exr");
  const FaceIdImage faces = readFaceIdExr(out / "corner.faceid.exr");
  ASSERT_EQ(luminance.width, 64);
  ASSERT_EQ(luminance.height, 48);
  // The floor box's faces come first: ids 1-6, its top among them.
  int floorPixels = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x) {
      if (faces.at(x, y) == 0 || faces.at(x, y) > 6) continue;
      ++floorPixels;
      EXPECT_NEAR(luminance.pixel(x, y)[1], 0.5 * e.at(x, y) / std::numbers::pi, 1e-6 * e.at(x, y));
    }
  EXPECT_GT(floorPixels, 64 * 48 / 4);

  const auto json = nlohmann::json::parse(readText(out / "render.json"));
  EXPECT_EQ(json["interval"], 2);
  EXPECT_EQ(json["views"][0]["name"], "corner");
  EXPECT_EQ(json["views"][0]["width_px"], 64);
  EXPECT_LT(json["views"][0]["exact_share"].get<double>(), 1.0);
  EXPECT_NE(r.out.find("corner"), std::string::npos) << r.out;
}

TEST(RenderCli, AnUnknownViewIsAnErrorThatListsTheViewsAndWritesNothing) {
  TempDir dir("penumbra-render-cli");
  writeScene(dir.path());
  const Result r = runPenumbra(dir.path(), "render scene.yaml --view window -o out");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("no view 'window'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("corner, top"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(RenderCli, BadOptionsAreUsageErrors) {
  TempDir dir("penumbra-render-cli");
  writeScene(dir.path());
  Result r = runPenumbra(dir.path(), "render scene.yaml -o out --spp 3");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("square"), std::string::npos) << r.err;
  r = runPenumbra(dir.path(), "render scene.yaml -o out --interval 0");
  EXPECT_EQ(r.status, 1);
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(RenderCli, ASceneWithoutViewsSaysHowToAddOne) {
  TempDir dir("penumbra-render-cli");
  std::string text = kScene;
  text.erase(text.find("views:"));
  std::ofstream(dir.path() / "scene.yaml") << text;
  const Result r = runPenumbra(dir.path(), "render scene.yaml -o out");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("no views"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("views:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(RenderCli, HelpTeachesOutputsAndUnits) {
  TempDir dir("penumbra-render-cli");
  const Result r = runPenumbra(dir.path(), "render --help");
  EXPECT_EQ(r.status, 0);
  for (const char* words : {"cd/m²", "lx", "faceid", "--interval", "--spp", "views:"})
    EXPECT_NE(r.out.find(words), std::string::npos) << words;
}

}  // namespace
}  // namespace penumbra
