// Round trips through the image files: what a render writes is what the tone map reads back.
#include "output/image_files.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "test_files.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

RgbImage randomHdr(int width, int height) {
  std::mt19937 random(7);
  // Ten decades of luminance, as a window beside a dark corner gives.
  std::uniform_real_distribution<float> exponent(-4.0f, 6.0f);
  RgbImage image(width, height);
  for (float& v : image.rgb) v = std::pow(10.0f, exponent(random));
  return image;
}

TEST(ImageFiles, ExrFloatIsExact) {
  const testing::TempDir dir("image-files");
  const RgbImage image = randomHdr(37, 21);
  writeRgbExr(dir.path() / "view.exr", image, {{"penumbra:view", "from-door"}});
  const RgbImage back = readRgbExr(dir.path() / "view.exr");
  ASSERT_EQ(back.width, 37);
  ASSERT_EQ(back.height, 21);
  EXPECT_EQ(back.rgb, image.rgb);
  const ImageMetadata metadata = readImageMetadata(dir.path() / "view.exr");
  EXPECT_NE(std::find(metadata.begin(), metadata.end(),
                      std::pair<std::string, std::string>{"penumbra:view", "from-door"}),
            metadata.end());
}

TEST(ImageFiles, FaceIdsKeepEveryBit) {
  const testing::TempDir dir("image-files");
  FaceIdImage ids(9, 5);
  // Values above 2^24 would not survive a float channel.
  for (size_t i = 0; i < ids.ids.size(); ++i) ids.ids[i] = static_cast<uint32_t>(i * 2654435761u);
  writeFaceIdExr(dir.path() / "view.faceid.exr", ids);
  const FaceIdImage back = readFaceIdExr(dir.path() / "view.faceid.exr");
  EXPECT_EQ(back.ids, ids.ids);
}

TEST(ImageFiles, ScalarAovIsExact) {
  const testing::TempDir dir("image-files");
  ScalarImage e(4, 3);
  for (size_t i = 0; i < e.values.size(); ++i) e.values[i] = 123.25f * static_cast<float>(i);
  writeScalarExr(dir.path() / "view.E.exr", e, "E");
  EXPECT_EQ(readScalarExr(dir.path() / "view.E.exr").values, e.values);
}

TEST(ImageFiles, RadianceHdrHoldsRadianceThatOpenImageIOReadsBack) {
  const testing::TempDir dir("image-files");
  const RgbImage image = randomHdr(16, 16);
  writeRadianceHdr(dir.path() / "view.hdr", image);
  // OpenImageIO's RGBE reader gives the file's radiance; Radiance's 179 lm/W turns it into cd/m².
  RgbImage back = readRgbExr(dir.path() / "view.hdr");
  for (float& v : back.rgb) v *= 179.0f;
  // RGBE shares one exponent per pixel: the largest channel keeps 8 bits of mantissa (0.4 %), a
  // channel many times smaller keeps fewer, so compare against the pixel's largest channel.
  double worst = 0.0;
  for (size_t p = 0; p < image.rgb.size(); p += 3) {
    const float largest = std::max({image.rgb[p], image.rgb[p + 1], image.rgb[p + 2]});
    for (int c = 0; c < 3; ++c) {
      worst = std::max(worst, std::abs(double(back.rgb[p + c]) - image.rgb[p + c]) / largest);
    }
  }
  EXPECT_LT(worst, 1.0 / 128.0);
}

TEST(ImageFiles, AFailedWriteLeavesNothing) {
  const testing::TempDir dir("image-files");
  RgbImage wrong(4, 4);
  wrong.rgb.pop_back();
  EXPECT_THROW(writeRgbExr(dir.path() / "view.exr", wrong), std::runtime_error);
  EXPECT_TRUE(fs::is_empty(dir.path()));
  EXPECT_THROW(readRgbExr(dir.path() / "missing.exr"), std::runtime_error);
}

TEST(ImageFiles, PngHoldsTheDisplayValues) {
  const testing::TempDir dir("image-files");
  DisplayImage image{3, 2, 3, {}};
  for (int i = 0; i < 18; ++i) image.values.push_back(static_cast<uint8_t>(i * 14));
  writePng(dir.path() / "view.png", image);
  const RgbImage back = readRgbExr(dir.path() / "view.png");  // OIIO reads PNG as 0..1 floats
  for (int i = 0; i < 18; ++i) EXPECT_FLOAT_EQ(back.rgb[i] * 255.0f, float(image.values[i]));
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir.path())) files.push_back(entry.path());
  EXPECT_EQ(files.size(), 1u);
}

}  // namespace
}  // namespace penumbra
