// `penumbra tonemap` as a user runs it: an EXR and its face ids in, a PNG and its statistics out;
// the PNG equals the library's toneMap() of the same images, and bad input is a usage error.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "output/image_files.hpp"
#include "output/tone_map_files.hpp"
#include "penumbra_process.hpp"
#include "png_reader.hpp"
#include "synthetic_images.hpp"
#include "test_files.hpp"
#include "tonemap/edge_contrast.hpp"
#include "tonemap/tone_map.hpp"

#include <OpenImageIO/imageio.h>

namespace penumbra {
namespace {

using testing::Result;
using testing::runPenumbra;

using testing::readPng;

TEST(ToneMapCli, WritesThePngAndItsStatistics) {
  const testing::TempDir dir("tonemap-cli");
  const testing::HdrScene scene = testing::roomView(96, 54, 3);
  writeRgbExr(dir.path() / "view.exr", scene.hdr);
  writeFaceIdExr(dir.path() / "view.faceid.exr", scene.faces);
  // --faces defaults to the name `penumbra render` gives the AOV beside the image.
  const Result r = runPenumbra(dir.path(), "tonemap view.exr -o view.png --black 0.05 -v");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("outer iterations"), std::string::npos) << r.err;
  ToneMapOptions options;
  options.black = 0.05;
  ToneMapStats expectedStats;
  const DisplayImage expected = toneMap(scene.hdr, scene.faces, options, &expectedStats);
  const DisplayImage written = readPng(dir.path() / "view.png");
  EXPECT_EQ(written.values, expected.values);
  const auto stats = nlohmann::json::parse(testing::readText(dir.path() / "view.tonemap.json"));
  EXPECT_EQ(stats["method"], "constraint");
  EXPECT_EQ(stats["black"], 0.05);
  EXPECT_EQ(stats["variables"], expectedStats.variables);
  EXPECT_EQ(stats["converged"], true);
  EXPECT_GT(stats["outer_iterations"].get<int>(), 0);
  EXPECT_TRUE(stats["residual"].contains("strong"));
  // Tagged as drive values in the display's own encoding (docs/tonemap.md).
  const ImageMetadata tags = readImageMetadata(dir.path() / "view.png");
  const auto tag = [&](const std::string& name) {
    for (const auto& [key, value] : tags) {
      if (key == name) return value;
    }
    return std::string();
  };
  EXPECT_EQ(tag("oiio:ColorSpace"), "sRGB");
  EXPECT_EQ(tag("penumbra:display"), "constraint");
  EXPECT_NE(tag("penumbra:values").find("drive values"), std::string::npos);
}

TEST(ToneMapCli, BaselinesGoThroughTheSameOutput) {
  const testing::TempDir dir("tonemap-cli");
  const testing::HdrScene scene = testing::roomView(64, 36, 2);
  writeRgbExr(dir.path() / "view.exr", scene.hdr);
  writeFaceIdExr(dir.path() / "faces.exr", scene.faces);
  for (const char* method : {"clip", "linear"}) {
    const Result r =
        runPenumbra(dir.path(), std::string("tonemap view.exr --faces faces.exr -o ") + method +
                                    ".png --display " + (method[0] == 'c' ? "CLIP" : method));
    ASSERT_EQ(r.status, 0) << r.err;
    ToneMapOptions options;
    options.method = std::string(method) == "clip" ? DisplayMethod::Clip : DisplayMethod::Linear;
    EXPECT_EQ(readPng(dir.path() / (std::string(method) + ".png")).values,
              toneMap(scene.hdr, scene.faces, options).values);
  }
}

// --exposure: a fixed white in cd/m² (the clip display), so that pictures compare: twice the
// luminance with twice the white is the very same PNG, and the statistics name the white.
TEST(ToneMapCli, AFixedExposureMapsTheSameLuminanceToTheSameValue) {
  const testing::TempDir dir("tonemap-cli");
  const testing::HdrScene scene = testing::roomView(64, 36, 2);
  RgbImage brighter = scene.hdr;
  for (float& v : brighter.rgb) v *= 2.0f;
  writeRgbExr(dir.path() / "view.exr", scene.hdr);
  writeRgbExr(dir.path() / "brighter.exr", brighter);
  writeFaceIdExr(dir.path() / "faces.exr", scene.faces);
  ASSERT_EQ(
      runPenumbra(dir.path(), "tonemap view.exr --faces faces.exr -o a.png --exposure 30").status,
      0);
  ASSERT_EQ(runPenumbra(dir.path(), "tonemap brighter.exr --faces faces.exr -o b.png --exposure 60")
                .status,
            0);
  ToneMapOptions options;
  options.method = DisplayMethod::Clip;
  options.white = 30;
  const DisplayImage a = readPng(dir.path() / "a.png");
  EXPECT_EQ(a.values, toneMap(scene.hdr, scene.faces, options).values);
  EXPECT_EQ(readPng(dir.path() / "b.png").values, a.values);
  const auto stats = nlohmann::json::parse(testing::readText(dir.path() / "a.tonemap.json"));
  EXPECT_EQ(stats["method"], "clip");
  EXPECT_EQ(stats["white_cdm2"], 30.0);
  // A fixed exposure is the clip display: another display with it is a usage error.
  const Result r = runPenumbra(
      dir.path(), "tonemap view.exr --faces faces.exr -o c.png --exposure 30 --display linear");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("--exposure"), std::string::npos) << r.err;
  EXPECT_EQ(runPenumbra(dir.path(), "tonemap view.exr -o c.png --exposure 0").status, 1);
}

TEST(ToneMapCli, BadInputIsAUsageError) {
  const testing::TempDir dir("tonemap-cli");
  const testing::HdrScene scene = testing::roomView(40, 30, 1);
  writeRgbExr(dir.path() / "view.exr", scene.hdr);
  writeFaceIdExr(dir.path() / "small.faceid.exr", FaceIdImage(20, 30));
  EXPECT_EQ(runPenumbra(dir.path(), "tonemap view.exr -o v.png --display sepia").status, 1);
  EXPECT_EQ(runPenumbra(dir.path(), "tonemap view.exr -o v.png --black 2").status, 1);
  // No faces beside the image: constraint needs them.
  Result r = runPenumbra(dir.path(), "tonemap view.exr -o v.png");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("faceid"), std::string::npos) << r.err;
  r = runPenumbra(dir.path(), "tonemap view.exr --faces small.faceid.exr -o v.png");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("size"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "v.png"));
}

}  // namespace
}  // namespace penumbra
