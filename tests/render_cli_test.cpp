// `penumbra render` as a user runs it: the files, their headers and units, and errors that write
// nothing.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <numbers>
#include <sstream>

#include "output/image_files.hpp"
#include "penumbra_process.hpp"
#include "png_reader.hpp"
#include "radiance_picture.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"
#include "tonemap/tone_map.hpp"

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
  // k = 4: at 64 × 48 the floor's E curves too much within two pixels for k = 2 to interpolate
  // any (the interval plan's curvature checks compute every sample then).
  const Result r = runPenumbra(dir.path(), "render scene.yaml --view corner -o out --interval 4");
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
  EXPECT_EQ(json["interval"], 4);
  EXPECT_EQ(json["views"][0]["name"], "corner");
  EXPECT_EQ(json["views"][0]["width_px"], 64);
  EXPECT_LT(json["views"][0]["exact_share"].get<double>(), 1.0);
  EXPECT_NE(r.out.find("corner"), std::string::npos) << r.out;
}

// --display-luminance and --ambient on `render`: the PNG is the library's tone map of the written
// luminance for that display, and render.json, the statistics and the PNG's tags name it.
TEST(RenderCli, TheTargetDisplayReachesThePngAndTheMetadata) {
  TempDir dir("penumbra-render-cli");
  writeScene(dir.path());
  const Result r = runPenumbra(dir.path(),
                               "render scene.yaml --view top -o out --direct-only --exposure 300 "
                               "--display-luminance 200 --ambient 50");
  if (r.status == 1 && r.err.find("device") != std::string::npos)
    GTEST_SKIP() << "no OpenCL device: " << r.err;
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path out = dir.path() / "out";
  ToneMapOptions options;
  options.method = DisplayMethod::Clip;
  options.white = 300;
  options.displayLuminance = 200;
  options.ambient = 50;
  EXPECT_EQ(
      readPng(out / "top.png").values,
      toneMap(readRgbExr(out / "top.exr"), readFaceIdExr(out / "top.faceid.exr"), options).values);
  const auto json = nlohmann::json::parse(readText(out / "render.json"));
  EXPECT_EQ(json["display_luminance_cdm2"], 200.0);
  EXPECT_EQ(json["ambient_lx"], 50.0);
  const auto stats = nlohmann::json::parse(readText(out / "top.tonemap.json"));
  EXPECT_EQ(stats["ambient_lx"], 50.0);
  EXPECT_EQ(metadataValue(out / "top.png", "penumbra:display_luminance"), "200 cd/m2");
  EXPECT_EQ(metadataValue(out / "top.png", "oiio:ColorSpace"), "sRGB");
}

// Radiance's VIEW= options as numbers by name: "-vp 1 2 3 -vh 70" → {"-vp": [1, 2, 3], ...}.
std::map<std::string, std::vector<double>> viewOptions(const std::string& text) {
  std::map<std::string, std::vector<double>> options;
  std::istringstream in(text);
  std::string word, current;
  while (in >> word) {
    if (word.starts_with("-v")) {  // an option; "-0.6" is a number
      current = word;
      options[current];
    } else {
      options[current].push_back(std::stod(word));
    }
  }
  return options;
}

TEST(RenderCli, TheRadiancePictureReadsBackByRadiancesRules) {
  TempDir dir("penumbra-render-cli");
  writeScene(dir.path());
  const Result r = runPenumbra(dir.path(), "render scene.yaml --view corner -o out");
  if (r.status == 1 && r.err.find("device") != std::string::npos)
    GTEST_SKIP() << "no OpenCL device: " << r.err;
  ASSERT_EQ(r.status, 0) << r.err;
  // The table has no material: the render says it reflects nothing, as `grid` does.
  EXPECT_NE(r.err.find("1 solid without a material reflects no light (black): table"),
            std::string::npos)
      << r.err;
  const RadiancePicture picture = readRadiancePicture(dir.path() / "out" / "corner.hdr");
  EXPECT_EQ(picture.value("FORMAT"), "32-bit_rle_rgbe");
  EXPECT_EQ(picture.value("EXPOSURE"), "1");
  EXPECT_EQ(picture.value("penumbra:view"), "corner");
  EXPECT_EQ(picture.value("penumbra:scene"), "scene.yaml");
  EXPECT_NE(picture.value("penumbra:units").find("179"), std::string::npos);

  // The camera of the view: eye [3.8, 3.8, 1.6], target [1.5, 1.5, 0.3], fov 70, 64 × 48.
  auto view = viewOptions(picture.value("VIEW"));
  EXPECT_TRUE(view.contains("-vtv")) << picture.value("VIEW");
  EXPECT_EQ(view["-vp"], (std::vector<double>{3.8, 3.8, 1.6}));
  const Vec3 direction = (Vec3(1.5, 1.5, 0.3) - Vec3(3.8, 3.8, 1.6)).normalized();
  ASSERT_EQ(view["-vd"].size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(view["-vd"][i], direction[i], 1e-12);
  EXPECT_EQ(view["-vu"], (std::vector<double>{0, 0, 1}));
  EXPECT_EQ(view["-vh"], (std::vector<double>{70}));
  // Square pixels: the half-angles' tangents are in the ratio of the sides.
  ASSERT_EQ(view["-vv"].size(), 1u);
  const double vv = view["-vv"][0] * std::numbers::pi / 180.0;
  EXPECT_NEAR(std::tan(vv / 2.0), std::tan(35.0 * std::numbers::pi / 180.0) * 48.0 / 64.0, 1e-12);

  // Radiance at 179 lm/W: pixel × 179 is the .exr's cd/m², within half a mantissa step of the
  // pixel's largest channel (a step is at most 1/128 of it).
  const RgbImage luminance = readRgbExr(dir.path() / "out" / "corner.exr");
  ASSERT_EQ(picture.width, luminance.width);
  ASSERT_EQ(picture.height, luminance.height);
  double worst = 0.0;
  int lit = 0;
  for (std::size_t p = 0; p < luminance.rgb.size(); p += 3) {
    const double largest = std::max({luminance.rgb[p], luminance.rgb[p + 1], luminance.rgb[p + 2]});
    if (largest == 0.0) {
      EXPECT_EQ(picture.rgb[p], 0.0f);
      continue;
    }
    ++lit;
    for (int c = 0; c < 3; ++c) {
      worst =
          std::max(worst, std::abs(179.0 * picture.rgb[p + c] - luminance.rgb[p + c]) / largest);
    }
  }
  EXPECT_GT(lit, 64 * 48 / 4);
  EXPECT_LE(worst, (1.0 + 1e-6) / 256.0);
  std::cout << "worst |179 · pixel − L| / L_max over " << lit << " pixels: " << worst << "\n";
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

const char* kCliScene = R"(penumbra: 1
materials: {grey: 0.5, wood: [0.4, 0.3, 0.2]}
room: {size: [4, 4, 2.8], materials: {floor: grey, ceiling: grey, walls: grey}}
solids:
  - {name: table, box: {min: [1, 1, 0.7], max: [2, 2, 0.75]}, material: wood}
sources:
  - {name: panel, rect: {center: [1.5, 2.5, 2.79], size: [0.6, 0.6], normal: [0, 0, -1]}, luminance: 3000}
views:
  - {name: corner, eye: [3.8, 3.8, 1.6], target: [1.5, 1.5, 0.9], fov: 80, size: [64, 48]}
)";

// `penumbra render` includes the interreflected light by default and says so in every header
// and in render.json; `--direct-only` gives the direct renderer's images bit for bit.
TEST(RenderCliLight, TotalByDefaultDirectOnlyBitForBit) {
  TempDir dir("penumbra-render-light");
  std::ofstream(dir.path() / "scene.yaml") << kCliScene;
  const Result total = runPenumbra(dir.path(), "render scene.yaml -o total -q");
  if (total.status == 1 && total.err.find("device") != std::string::npos)
    GTEST_SKIP() << "no OpenCL device: " << total.err;
  ASSERT_EQ(total.status, 0) << total.err;
  const Result direct = runPenumbra(dir.path(), "render scene.yaml -o direct -q --direct-only");
  ASSERT_EQ(direct.status, 0) << direct.err;
  const fs::path t = dir.path() / "total", d = dir.path() / "direct";
  for (const char* file : {"corner.exr", "corner.E.exr", "corner.png"}) {
    EXPECT_EQ(metadataValue(t / file, "penumbra:light"), "total (direct + interreflected)");
    EXPECT_EQ(metadataValue(d / file, "penumbra:light"), "direct only");
  }
  const nlohmann::json tj = nlohmann::json::parse(std::ifstream(t / "render.json"));
  const nlohmann::json dj = nlohmann::json::parse(std::ifstream(d / "render.json"));
  EXPECT_EQ(tj["light"], "total (direct + interreflected)");
  EXPECT_EQ(dj["light"], "direct only");
  EXPECT_GT(tj["interreflection"]["elements"].get<int>(), 0);
  EXPECT_FALSE(dj.contains("interreflection"));

  // The direct renderer in this process, on the same scene and view.
  const Scene scene = loadScene(dir.path() / "scene.yaml");
  Renderer renderer(cpuDevice(), scene);
  const RenderedView reference = renderer.render(scene.views.front(), RenderOptions{});
  const RgbImage dl = readRgbExr(d / "corner.exr"), tl = readRgbExr(t / "corner.exr");
  const ScalarImage de = readScalarExr(d / "corner.E.exr"), te = readScalarExr(t / "corner.E.exr");
  EXPECT_EQ(dl.rgb, reference.luminance.rgb);
  EXPECT_EQ(de.values, reference.illuminance.values);
  // The total adds light to every pixel that shows a solid: the room is closed.
  int lit = 0;
  for (std::size_t i = 0; i < de.values.size(); ++i) {
    if (reference.faces.ids[i] == FaceIdImage::kNoSurface) continue;
    if (de.values[i] == 0.0f && dl.rgb[i * 3 + 1] > 0.0f) continue;  // the panel
    EXPECT_GT(te.values[i], de.values[i]) << "pixel " << i;
    EXPECT_GE(tl.rgb[i * 3 + 1], dl.rgb[i * 3 + 1]) << "pixel " << i;
    ++lit;
  }
  EXPECT_GT(lit, 64 * 48 / 2);
}

}  // namespace
}  // namespace penumbra
