// Spaces 0-4 against the thesis's own HSV code (Fig. 4.2 and 4.3, transcribed here): hue and
// saturation survive the tone map, only V changes.
#include "tonemap/display_spaces.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace penumbra {
namespace {

struct Hsv {
  double h, s, v;
};

Hsv rgbToHsv(double r, double g, double b) {  // Fig. 4.2
  Hsv out{0, 0, std::max({r, g, b})};
  const double delta = out.v - std::min({r, g, b});
  out.s = out.v == 0 ? 0 : delta / out.v;
  if (out.s == 0) return out;
  if (r == out.v) {
    out.h = (g - b) / delta;
  } else if (g == out.v) {
    out.h = 2 + (b - r) / delta;
  } else {
    out.h = 4 + (r - g) / delta;
  }
  out.h *= 60;
  if (out.h < 0) out.h += 360;
  return out;
}

void hsvToRgb(Hsv c, double rgb[3]) {  // Fig. 4.3
  if (c.s == 0) {
    rgb[0] = rgb[1] = rgb[2] = c.v;
    return;
  }
  double h = c.h == 360 ? 0 : c.h;
  h /= 60;
  const int i = static_cast<int>(std::floor(h));
  const double f = h - i, p = c.v * (1 - c.s), q = c.v * (1 - c.s * f),
               t = c.v * (1 - c.s * (1 - f));
  const double table[6][3] = {{c.v, t, p}, {q, c.v, p}, {p, c.v, t},
                              {p, q, c.v}, {t, p, c.v}, {c.v, p, q}};
  for (int k = 0; k < 3; ++k) rgb[k] = table[i][k];
}

TEST(DisplaySpaces, DeviceImageIsTheThesisHsvRoundTripWithTheNewV) {
  std::mt19937 random(2);
  std::uniform_real_distribution<float> exponent(-2.0f, 4.0f);
  RgbImage hdr(23, 11);
  for (float& v : hdr.rgb) v = std::pow(10.0f, exponent(random));
  const double black = 0.05;
  const DisplaySpaces spaces = displaySpaces(hdr, black);
  ScalarImage display(23, 11);
  std::uniform_real_distribution<float> value(black, 1.0f);
  for (float& v : display.values) v = value(random);
  const DisplayImage device = deviceImage(hdr, spaces, display);
  double lo = INFINITY, hi = 0;
  for (float v : hdr.rgb) lo = std::min<double>(lo, v), hi = std::max<double>(hi, v);
  for (size_t i = 0; i < display.values.size(); ++i) {
    const float* c = &hdr.rgb[i * 3];
    // Space 1 (eq. 4.9-4.11), Space 2, Space 3 (eq. 4.12), new V, back, Space 4 (eq. 4.13-4.15).
    Hsv hsv = rgbToHsv((c[0] - lo) / (hi - lo), (c[1] - lo) / (hi - lo), (c[2] - lo) / (hi - lo));
    EXPECT_NEAR(spaces.value1[i], hsv.v, 1e-6);
    EXPECT_NEAR(spaces.value3[i], black + (1 - black) * hsv.v, 1e-6);
    hsv.v = display.values[i];
    double rgb[3];
    hsvToRgb(hsv, rgb);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(device.values[i * 3 + k], std::round(255 * rgb[k]), 1.0) << i << " " << k;
    }
  }
}

// A daylit view: the room's surfaces (face ids) between 2 and 300 cd/m², the sky through the
// window at 2 000 cd/m² and the sun's disk at 6.3e8 cd/m² (no face). The surfaces keep the range
// they have without the background (Space 1 over [2, 300]), and
// the background above it shows V = 1: white, not a room crushed to black by the sun.
TEST(DisplaySpaces, WhatTheWindowShowsDoesNotSetTheRoomsRange) {
  RgbImage hdr(4, 1);
  FaceIdImage faces(4, 1);
  const float luminance[4] = {2.0f, 300.0f, 2000.0f, 6.3e8f};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) hdr.rgb[i * 3 + c] = luminance[i];
  faces.ids[0] = 1;
  faces.ids[1] = 2;
  const double black = 0.05;
  const DisplaySpaces room = displaySpaces(hdr, black, &faces);
  EXPECT_DOUBLE_EQ(room.maxRgb, 300.0);
  EXPECT_FLOAT_EQ(room.value1[0], 0.0f);
  EXPECT_FLOAT_EQ(room.value1[1], 1.0f);
  EXPECT_FLOAT_EQ(room.value1[2], 1.0f);
  EXPECT_FLOAT_EQ(room.value3[3], 1.0f);
  ScalarImage display(4, 1);
  display.values = room.value3;
  const DisplayImage device = deviceImage(hdr, room, display);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(device.values[2 * 3 + c], 255);
    EXPECT_EQ(device.values[3 * 3 + c], 255);
  }
  // Without the face ids the sun sets the range and the room is black to within 1e-6.
  const DisplaySpaces whole = displaySpaces(hdr, black);
  EXPECT_LT(whole.value1[1], 1e-6);
}

}  // namespace
}  // namespace penumbra
