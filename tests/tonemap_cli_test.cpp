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

#include <algorithm>
#include <cmath>
#include <numbers>

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
  // Tagged as sRGB code values of display luminance (docs/tonemap.md).
  const ImageMetadata tags = readImageMetadata(dir.path() / "view.png");
  const auto tag = [&](const std::string& name) {
    for (const auto& [key, value] : tags) {
      if (key == name) return value;
    }
    return std::string();
  };
  EXPECT_EQ(tag("oiio:ColorSpace"), "sRGB");
  EXPECT_EQ(tag("penumbra:display"), "constraint");
  EXPECT_NE(tag("penumbra:values").find("sRGB code values"), std::string::npos);
  EXPECT_EQ(tag("penumbra:display_luminance"), "100 cd/m2");
  EXPECT_EQ(stats["display_luminance_cdm2"], 100.0);
  EXPECT_EQ(stats["ambient_lx"], 0.0);
  EXPECT_EQ(stats["lower_bound"], 0.05);
}

// The PNG's own chunks, read from its bytes: sRGB (rendering intent), gAMA 1/2.2 as the PNG
// specification's sRGB fallback gives it (45455) and cHRM with the Rec. 709 primaries and the D65
// white (× 100 000), before the image data; the pixels have no other colour chunk.
TEST(ToneMapCli, ThePngIsTaggedSrgbInItsChunks) {
  const testing::TempDir dir("tonemap-cli");
  const testing::HdrScene scene = testing::roomView(48, 27, 2);
  writeRgbExr(dir.path() / "view.exr", scene.hdr);
  writeFaceIdExr(dir.path() / "view.faceid.exr", scene.faces);
  ASSERT_EQ(runPenumbra(dir.path(), "tonemap view.exr -o view.png").status, 0);
  const std::vector<testing::PngChunk> chunks = testing::readPngChunks(dir.path() / "view.png");
  const auto find = [&](const std::string& type) {
    return std::find_if(chunks.begin(), chunks.end(),
                        [&](const testing::PngChunk& c) { return c.type == type; });
  };
  ASSERT_FALSE(chunks.empty());
  EXPECT_EQ(chunks.front().type, "IHDR");
  const auto srgb = find("sRGB"), gama = find("gAMA"), chrm = find("cHRM"), idat = find("IDAT");
  ASSERT_NE(srgb, chunks.end());
  ASSERT_NE(gama, chunks.end());
  ASSERT_NE(chrm, chunks.end());
  ASSERT_NE(idat, chunks.end());
  EXPECT_LT(srgb, idat);
  EXPECT_LT(gama, idat);
  EXPECT_LT(chrm, idat);
  ASSERT_EQ(srgb->data.size(), 1u);
  EXPECT_LE(srgb->data[0], 3);  // one of the four rendering intents
  ASSERT_EQ(gama->data.size(), 4u);
  EXPECT_EQ(testing::pngUint32(gama->data.data()), 45455u);
  ASSERT_EQ(chrm->data.size(), 32u);
  const uint32_t rec709[8] = {31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000};
  for (int i = 0; i < 8; ++i) EXPECT_EQ(testing::pngUint32(&chrm->data[4 * i]), rec709[i]) << i;
  EXPECT_EQ(find("iCCP"), chunks.end());  // sRGB and iCCP exclude each other
}

// --display-luminance and --ambient: a grey picture with a fixed exposure shows each pixel's
// luminance L at the display luminance V·(Lmax + R), V = L / white cut to [black, 1], R = 0.01
// E/π reflected; its code value inverts L = (Lmax − Lblack) F(code) + Lblack + R. The options are
// in the statistics and the PNG's text chunks.
TEST(ToneMapCli, TheDisplayOptionsEncodeForThatDisplay) {
  const testing::TempDir dir("tonemap-cli");
  RgbImage grey(64, 1);
  FaceIdImage faces(64, 1);
  for (int x = 0; x < 64; ++x) {
    const float l = 0.5f * static_cast<float>(std::pow(1.1, x));  // 0.5 to 205 cd/m²
    for (int c = 0; c < 3; ++c) grey.pixel(x, 0)[c] = l;
    faces.ids[x] = 1;
  }
  writeRgbExr(dir.path() / "grey.exr", grey);
  writeFaceIdExr(dir.path() / "grey.faceid.exr", faces);
  const double white = 120, peak = 250, ambient = 400, black = 0.01;
  const Result r = runPenumbra(dir.path(),
                               "tonemap grey.exr -o grey.png --exposure 120 --black 0.01 "
                               "--display-luminance 250 --ambient 400");
  ASSERT_EQ(r.status, 0) << r.err;
  const double reflected = 0.01 * ambient / std::numbers::pi;
  const double lowerBound = (black * peak + reflected) / (peak + reflected);
  const DisplayImage png = readPng(dir.path() / "grey.png");
  int between = 0;
  for (int x = 0; x < 64; ++x) {
    const double v = std::clamp(grey.pixel(x, 0)[0] / white, lowerBound, 1.0);
    const double shown = v * (peak + reflected);
    const double code =
        testing::srgbCodeOf((shown - black * peak - reflected) / (peak - black * peak));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(png.values[x * 3 + c], 255 * code, 0.5 + 1e-6) << x;
    between += v > lowerBound && v < 1;
  }
  EXPECT_GT(between, 20);
  const auto stats = nlohmann::json::parse(testing::readText(dir.path() / "grey.tonemap.json"));
  EXPECT_EQ(stats["display_luminance_cdm2"], peak);
  EXPECT_EQ(stats["ambient_lx"], ambient);
  EXPECT_NEAR(stats["lower_bound"].get<double>(), lowerBound, 1e-15);
  bool tagged = false;
  for (const auto& [key, value] : readImageMetadata(dir.path() / "grey.png"))
    tagged |= key == "penumbra:ambient" && value.starts_with("400 lx");
  EXPECT_TRUE(tagged);
  EXPECT_EQ(runPenumbra(dir.path(), "tonemap grey.exr -o bad.png --display-luminance 0").status, 1);
  EXPECT_EQ(runPenumbra(dir.path(), "tonemap grey.exr -o bad.png --ambient -5").status, 1);
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
