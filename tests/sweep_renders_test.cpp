// Renders per case of a sweep (`renders: [view]` in a study): the case folders hold the views,
// and a reflectance sweep changes the image by exactly the reflectance, not the illuminance.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "output/image_files.hpp"
#include "png_reader.hpp"
#include "scene/scene_loader.hpp"
#include "study/case_renders.hpp"
#include "study/study_reader.hpp"
#include "study/sweep_runner.hpp"
#include "test_files.hpp"
#include "tonemap/tone_map.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using testing::readPng;
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

// The study of kScene in `dir` with the renders exposed as `exposure` (sweep --exposure), and
// the settings of a sweep of it into dir/out on the CPU, direct light only.
struct RenderSweep {
  Study study;
  SweepSettings settings;
};
RenderSweep renderSweep(const fs::path& dir, const std::string& exposure) {
  write(dir / "scene.yaml", kScene);
  write(dir / "study.yaml", kStudy);
  RenderSweep sweep{loadStudy(dir / "study.yaml"), {}};
  sweep.study.renderExposure = exposure;
  sweep.settings.output = dir / "out";
  sweep.settings.estimator.device = "cpu";
  // Direct light only: the cases then differ on the floor alone, and every other face shows the
  // same luminance in both.
  sweep.settings.estimator.interreflection = false;
  sweep.settings.version = "test";
  sweep.settings.caseOutputs = {std::make_shared<CaseRenders>(
      sweep.study.renders, sweep.settings.estimator, exposure, sweep.settings.output)};
  return sweep;
}

// With a fixed exposure (`sweep --exposure 40`) every case's PNG shows a luminance L as the code
// value that shows V = L / 40 cd/m² of the display's white (cut to its black and white): the same
// cd/m² is the same pixel value in both cases, the floor (its reflectance tripled) three times as
// bright.
TEST(SweepRenders, AFixedExposureShowsTheSameLuminanceAsTheSamePixelValueInEveryCase) {
  TempDir dir("penumbra-sweep-renders");
  const double white = 40.0, black = ToneMapOptions{}.black;  // cd/m²; fraction of white
  const RenderSweep sweep = renderSweep(dir.path(), "40");
  SweepObserver silent;
  runSweep(sweep.study, sweep.settings, silent);
  std::vector<RgbImage> luminance;
  std::vector<DisplayImage> png;
  for (const char* folder : {"out/cases/case-001", "out/cases/case-002"}) {
    luminance.push_back(readRgbExr(dir.path() / folder / "corner.exr"));
    png.push_back(readPng(dir.path() / folder / "corner.png"));
  }
  int same = 0, shown = 0;
  for (int y = 0; y < png[0].height; ++y)
    for (int x = 0; x < png[0].width; ++x) {
      std::array<int, 2> drive{};
      for (int c = 0; c < 2; ++c) {
        const float* rgb = luminance[c].pixel(x, y);
        const double v = std::clamp(std::max({rgb[0], rgb[1], rgb[2]}) / white, black, 1.0);
        const size_t at = (static_cast<size_t>(y) * png[c].width + x) * png[c].channels;
        drive[c] = *std::max_element(&png[c].values[at], &png[c].values[at] + 3);
        // Rounded to the nearest of 256 levels.
        EXPECT_NEAR(drive[c], testing::expectedCode(v, black), 0.5 + 1e-3) << x << "," << y;
        if (v > black && v < 1.0) ++shown;
      }
      if (luminance[0].pixel(x, y)[1] == luminance[1].pixel(x, y)[1]) {
        EXPECT_EQ(drive[0], drive[1]) << x << "," << y;
        ++same;
      }
    }
  EXPECT_GT(same, 48 * 32 / 8);
  EXPECT_GT(shown, 48 * 32 / 4);  // most pixels lie between black and white, not cut
}

// auto-first: the first case is exposed automatically (clip's log average at 18 %), and its white
// is kept (OUT/exposure.json) for every other case, also for those a later run adds.
TEST(SweepRenders, AutoFirstExposesEveryCaseWithTheFirstCasesWhite) {
  TempDir dir("penumbra-sweep-renders");
  SweepObserver silent;
  // Case 1 first, case 2 by a later run (a new writer, as a new process has).
  for (const Shard shard : {Shard{1, 2}, Shard{2, 2}}) {
    RenderSweep sweep = renderSweep(dir.path(), "auto-first");
    sweep.settings.shard = shard;
    runSweep(sweep.study, sweep.settings, silent);
  }
  const fs::path first = dir.path() / "out/cases/case-001";
  ToneMapOptions automatic;
  automatic.method = DisplayMethod::Clip;
  ToneMapStats firstStats;
  toneMap(readRgbExr(first / "corner.exr"), readFaceIdExr(first / "corner.faceid.exr"), automatic,
          &firstStats);
  const double white =
      nlohmann::json::parse(readText(dir.path() / "out/exposure.json"))["white_cdm2"];
  EXPECT_EQ(white, firstStats.white);
  for (const char* folder : {"out/cases/case-001", "out/cases/case-002"}) {
    const auto stats = nlohmann::json::parse(readText(dir.path() / folder / "corner.tonemap.json"));
    EXPECT_EQ(stats["method"], "clip") << folder;
    EXPECT_EQ(stats["white_cdm2"], white) << folder;
  }
}

// kScene with the panel's flux varied, 3000 and 6000 lm: direct light only, the second case's
// luminance is twice the first's at every pixel.
RenderSweep fluxSweep(const fs::path& dir, const std::string& exposure) {
  RenderSweep sweep = renderSweep(dir, exposure);
  std::string scene = kScene;
  scene.replace(scene.find("flux: 3000"), 10, "flux: \"${flux}\"");
  scene.replace(scene.find("{floor_reflectance: 0.2}"), 24, "{floor_reflectance: 0.2, flux: 3000}");
  write(dir / "scene.yaml", scene);
  write(dir / "study.yaml",
        "penumbra-study: 1\nscene: scene.yaml\nparameters:\n  flux: [3000, "
        "6000]\nrenders: [corner]\n");
  sweep.study = loadStudy(dir / "study.yaml");
  sweep.study.renderExposure = exposure;
  return sweep;
}

// The largest channel of each pixel of a case's PNG.
std::vector<int> drives(const fs::path& png) {
  const DisplayImage image = readPng(png);
  std::vector<int> values;
  for (size_t at = 0; at < image.values.size(); at += image.channels)
    values.push_back(*std::max_element(&image.values[at], &image.values[at] + 3));
  return values;
}

// auto-all: one white for the whole study, the geometric mean of the cases' own automatic whites
// (each computed here from the case's .exr); with it a pixel of twice the luminance shows twice
// the display luminance. Exposed case by case instead, the two PNGs are the same picture.
TEST(SweepRenders, AutoAllExposesTheWholeStudyWithOneWhite) {
  TempDir dir("penumbra-sweep-renders");
  SweepObserver silent;
  fs::create_directories(dir.path() / "each");
  const RenderSweep each = fluxSweep(dir.path() / "each", "");
  runSweep(each.study, each.settings, silent);
  EXPECT_EQ(drives(dir.path() / "each/out/cases/case-001/corner.png"),
            drives(dir.path() / "each/out/cases/case-002/corner.png"));

  fs::create_directories(dir.path() / "all");
  const RenderSweep sweep = fluxSweep(dir.path() / "all", "auto-all");
  runSweep(sweep.study, sweep.settings, silent);
  std::array<double, 2> own{};
  std::array<RgbImage, 2> luminance;
  for (int c = 0; c < 2; ++c) {
    const fs::path folder = dir.path() / "all/out/cases" / (c == 0 ? "case-001" : "case-002");
    luminance[c] = readRgbExr(folder / "corner.exr");
    ToneMapOptions automatic;
    automatic.method = DisplayMethod::Clip;
    ToneMapStats stats;
    toneMap(luminance[c], readFaceIdExr(folder / "corner.faceid.exr"), automatic, &stats);
    own[c] = stats.white;
  }
  EXPECT_NEAR(own[1], 2.0 * own[0], 1e-5 * own[1]);  // luminance ∝ flux
  const auto kept = nlohmann::json::parse(readText(dir.path() / "all/out/exposure.json"));
  const double white = kept["white_cdm2"];
  EXPECT_NEAR(white, std::sqrt(own[0] * own[1]), 1e-12 * white);
  EXPECT_EQ(kept["pictures"], 2);
  const double black = ToneMapOptions{}.black;
  std::array<std::vector<int>, 2> drive;
  for (int c = 0; c < 2; ++c) {
    const fs::path folder = dir.path() / "all/out/cases" / (c == 0 ? "case-001" : "case-002");
    const auto stats = nlohmann::json::parse(readText(folder / "corner.tonemap.json"));
    EXPECT_EQ(stats["white_cdm2"], white);
    drive[c] = drives(folder / "corner.png");
  }
  int doubled = 0;
  for (size_t i = 0; i < drive[0].size(); ++i) {
    const int x = static_cast<int>(i) % luminance[0].width,
              y = static_cast<int>(i) / luminance[0].width;
    for (int c = 0; c < 2; ++c) {
      const float* rgb = luminance[c].pixel(x, y);
      const double v = std::clamp(std::max({rgb[0], rgb[1], rgb[2]}) / white, black, 1.0);
      EXPECT_NEAR(drive[c][i], testing::expectedCode(v, black), 0.5 + 1e-3) << x << "," << y;
    }
    // Between black and white in both: twice the display luminance, to the rounding of each
    // code (half a step either way).
    const auto shown = [&](double code) {
      return black + (1 - black) * testing::srgbLinearOf(code / 255.0);
    };
    if (drive[0][i] > 1 && drive[1][i] < 255) {
      const double step = shown(drive[1][i] + 0.5) - shown(drive[1][i] - 0.5) +
                          2 * (shown(drive[0][i] + 0.5) - shown(drive[0][i] - 0.5));
      EXPECT_NEAR(shown(drive[1][i]), 2.0 * shown(drive[0][i]), 0.5 * step + 1e-9) << x << "," << y;
      ++doubled;
    }
  }
  EXPECT_GT(doubled, 48 * 32 / 4);
}

// auto-all over runs: a later run (a shard, --resume) exposes again the cases an earlier one
// wrote, so that every case of the folder shares the white of all of them.
TEST(SweepRenders, AutoAllExposesAgainTheCasesOfEarlierRuns) {
  TempDir dir("penumbra-sweep-renders");
  SweepObserver silent;
  const auto whiteOf = [&](const char* folder) {
    return nlohmann::json::parse(
               readText(dir.path() / "out/cases" / folder / "corner.tonemap.json"))["white_cdm2"]
        .get<double>();
  };
  RenderSweep first = fluxSweep(dir.path(), "auto-all");
  first.settings.shard = Shard{1, 2};
  runSweep(first.study, first.settings, silent);
  const double alone = whiteOf("case-001");  // its own automatic white: the only picture
  EXPECT_FALSE(fs::exists(dir.path() / "out/cases/case-002"));
  RenderSweep second = fluxSweep(dir.path(), "auto-all");
  second.settings.shard = Shard{2, 2};
  runSweep(second.study, second.settings, silent);
  // Case 2 has twice the luminance: its own white is twice case 1's, and the shared one √2 times.
  EXPECT_NEAR(whiteOf("case-001"), std::sqrt(2.0) * alone, 1e-5 * alone);
  EXPECT_EQ(whiteOf("case-002"), whiteOf("case-001"));
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

// `sweep --display-luminance 250 --ambient 400`: the target display is part of the renders' name,
// so a folder rendered for the default display is computed again, and every case's PNG (auto-all
// exposes them again after the cases) is encoded for that display, as its statistics and
// render.json say.
TEST(SweepRenders, TheTargetDisplayIsPartOfTheRendersAndEveryCaseUsesIt) {
  TempDir dir("penumbra-sweep-renders");
  SweepObserver silent;
  const RenderSweep standard = fluxSweep(dir.path(), "auto-all");
  EXPECT_EQ(runSweep(standard.study, standard.settings, silent).computed, 2u);

  RenderSweep other = fluxSweep(dir.path(), "auto-all");
  ToneMapOptions display;
  display.displayLuminance = 250;
  display.ambient = 400;
  other.study.renderDisplay = renderDisplayName(display);
  EXPECT_EQ(other.study.renderDisplay, "display=250cd/m2,ambient=400lx");
  other.settings.caseOutputs = {std::make_shared<CaseRenders>(
      other.study.renders, other.settings.estimator, "auto-all", other.settings.output, display)};
  const SweepSummary summary = runSweep(other.study, other.settings, silent);
  EXPECT_EQ(summary.computed, 2u);
  EXPECT_EQ(summary.recomputed, 2u);
  const double reflected = 0.01 * 400 / std::numbers::pi;
  const double lowerBound = (ToneMapOptions{}.black * 250 + reflected) / (250 + reflected);
  for (const char* folder : {"out/cases/case-001", "out/cases/case-002"}) {
    const auto stats = nlohmann::json::parse(readText(dir.path() / folder / "corner.tonemap.json"));
    EXPECT_EQ(stats["display_luminance_cdm2"], 250.0) << folder;
    EXPECT_EQ(stats["ambient_lx"], 400.0) << folder;
    EXPECT_NEAR(stats["lower_bound"].get<double>(), lowerBound, 1e-15) << folder;
    const auto render = nlohmann::json::parse(readText(dir.path() / folder / "render.json"));
    EXPECT_EQ(render["display_luminance_cdm2"], 250.0) << folder;
    EXPECT_EQ(render["ambient_lx"], 400.0) << folder;
  }
}

}  // namespace
}  // namespace penumbra
