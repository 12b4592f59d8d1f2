// The target display (tonemap/display_model.hpp): the sRGB transfer function against its
// published values, the model's closed form at black, white and mid-grey, and code value →
// luminance → code value round trips on displays with and without ambient light.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tonemap/display_model.hpp"
#include "tonemap/tone_map_options.hpp"

namespace penumbra {
namespace {

// A desk monitor in the dark, a bright one in a lit office, a dim one beside a window.
const DisplayModel kDisplays[] = {{100.0, 0.02, 0.0}, {400.0, 0.001, 500.0}, {80.0, 0.05, 2000.0}};

// IEC 61966-2-1: code 0.5 shows 21.404 % of white; 18 % grey (photographic middle grey) is code
// 0.46136 (117.6 of 255); the two pieces meet at 0.04045 ↔ 0.0031308.
TEST(DisplayModel, TheSrgbCurveHasItsPublishedValues) {
  EXPECT_NEAR(srgbDecode(0.5), 0.214041140, 1e-9);
  EXPECT_NEAR(srgbEncode(0.18), 0.461356130, 1e-9);
  EXPECT_NEAR(srgbDecode(0.04045), 0.0031308, 1e-8);
  EXPECT_NEAR(srgbEncode(0.0031308), 0.04045, 1e-6);
  EXPECT_EQ(srgbDecode(0.0), 0.0);
  EXPECT_EQ(srgbEncode(0.0), 0.0);
  EXPECT_NEAR(srgbDecode(1.0), 1.0, 1e-15);
  EXPECT_NEAR(srgbEncode(1.0), 1.0, 1e-15);
}

// L = (Lmax − Lblack)·F(V) + Lblack + k·E/π with k = 0.01, written out for each display.
TEST(DisplayModel, BlackWhiteAndMidGreyAreTheClosedForm) {
  for (const DisplayModel& d : kDisplays) {
    const double lblack = d.blackShare * d.peakLuminance;
    const double reflected = 0.01 * d.ambient / std::numbers::pi;
    EXPECT_NEAR(d.luminance(0.0), lblack + reflected, 1e-12 * d.peakLuminance);
    EXPECT_NEAR(d.luminance(1.0), d.peakLuminance + reflected, 1e-12 * d.peakLuminance);
    EXPECT_NEAR(d.luminance(0.5), (d.peakLuminance - lblack) * 0.214041140 + lblack + reflected,
                1e-8 * d.peakLuminance);
    EXPECT_NEAR(d.lowerBound(), (lblack + reflected) / (d.peakLuminance + reflected), 1e-15);
    // 18 % of the panel's own range above its black is code 0.46136.
    EXPECT_NEAR(d.codeValue(lblack + reflected + 0.18 * (d.peakLuminance - lblack)), 0.461356130,
                1e-9);
  }
  // 500 lx on a 100 cd/m² monitor with a 2 cd/m² black: 5/π cd/m² reflected.
  EXPECT_NEAR((DisplayModel{100.0, 0.02, 500.0}.luminance(0.0)), 2.0 + 5.0 / std::numbers::pi,
              1e-12);
}

// Without ambient light the display's lower bound is the black share as given, bit for bit, so
// that the tone map's bounds (`--black`) stay exact.
TEST(DisplayModel, WithoutAmbientTheLowerBoundIsTheBlackShare) {
  for (double black : {0.02, 0.05, 1e-4, 0.3}) {
    EXPECT_EQ((DisplayModel{100.0, black, 0.0}.lowerBound()), black);
    EXPECT_EQ((DisplayModel{273.0, black, 0.0}.lowerBound()), black);
  }
  ToneMapOptions options;
  options.black = 0.05;
  options.ambient = 300;
  EXPECT_GT(options.targetDisplay().lowerBound(), 0.05);  // ambient light lifts the black
}

TEST(DisplayModel, CodeToLuminanceToCodeRoundTrips) {
  for (const DisplayModel& d : kDisplays) {
    for (int code = 0; code <= 255; ++code) {
      const double v = code / 255.0;
      const double l = d.luminance(v);
      EXPECT_NEAR(d.codeValue(l), v, 1e-12) << code;
      // And from the other side: a share of the brightest that the display shows.
      const double share = l / d.brightest();
      EXPECT_NEAR(d.codeValueOfShare(share), v, 1e-12) << code;
      EXPECT_NEAR(std::lround(255.0 * d.codeValueOfShare(share)), code, 0) << code;
    }
    // Luminance the display cannot show is cut to its black and white.
    EXPECT_EQ(d.codeValue(0.5 * d.darkest()), 0.0);
    EXPECT_EQ(d.codeValue(2.0 * d.brightest()), 1.0);
  }
}

}  // namespace
}  // namespace penumbra
