// TMQI (host/tonemap/tmqi.*) on what must hold for any faithful implementation of Yeganeh & Wang
// 2013. No published score can be reproduced from a synthetic description: the authors' and the
// ports' examples are photographs (and the ports differ from the MATLAB code in the downsampling
// border and the naturalness blocks), so the checks are the measure's invariants: a display image
// that is the HDR image's own linear copy keeps its structure (S near 1), noise and blur lose it
// step by step, and N against the closed forms of the two fitted densities.
#include "tonemap/tmqi.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace penumbra {
namespace {

constexpr int kSize = 256;

// A small-range HDR luminance (40-200 cd/m², nothing to clip) with structure at every scale
// TMQI looks at: gratings of wavelength 6 to 96 pixels, so that each of the five scales (1 to 1/16
// of the size) sees one near its finest.
ScalarImage texturedLuminance() {
  ScalarImage image(kSize, kSize);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      double value = 120;
      double wavelength = 6, amplitude = 14;
      for (int k = 0; k < 5; ++k, wavelength *= 2) {
        const double phase = 0.7 * k;
        value += amplitude * std::sin(2 * std::numbers::pi * x / wavelength + phase) *
                 std::sin(2 * std::numbers::pi * y / wavelength + 1.3 * phase);
      }
      image.at(x, y) = static_cast<float>(value);
    }
  }
  return image;
}

// The display image a linear map gives: luminance / white × 255, cut to [0, 255].
ScalarImage linearCopy(const ScalarImage& hdr, double white) {
  ScalarImage ldr(hdr.width, hdr.height);
  for (size_t i = 0; i < hdr.values.size(); ++i) {
    ldr.values[i] = static_cast<float>(std::clamp(hdr.values[i] / white * 255, 0.0, 255.0));
  }
  return ldr;
}

ScalarImage withNoise(ScalarImage ldr, double sigma, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> noise(0, sigma);
  for (float& v : ldr.values) v = static_cast<float>(std::clamp(v + noise(random), 0.0, 255.0));
  return ldr;
}

// A (2r + 1)² box blur, the border clamped.
ScalarImage boxBlurred(const ScalarImage& image, int radius) {
  ScalarImage out(image.width, image.height);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      double sum = 0;
      for (int j = -radius; j <= radius; ++j) {
        for (int i = -radius; i <= radius; ++i) {
          sum += image.at(std::clamp(x + i, 0, image.width - 1),
                          std::clamp(y + j, 0, image.height - 1));
        }
      }
      out.at(x, y) = static_cast<float>(sum / ((2 * radius + 1) * (2 * radius + 1)));
    }
  }
  return out;
}

TEST(Tmqi, LinearCopyKeepsTheStructure) {
  const ScalarImage hdr = texturedLuminance();
  // In float, the copy's local structure is the HDR image's own (correlation 1) and strong
  // enough to be seen at every scale: every term of the local map is 1 up to rounding.
  const TmqiScore exact = structuralFidelity(hdr, linearCopy(hdr, 220));
  EXPECT_NEAR(exact.structuralFidelity, 1.0, 1e-9);
  for (double s : exact.scaleFidelity) EXPECT_NEAR(s, 1.0, 1e-9);
  // Rounded to 8 bits: 0.99996 measured.
  ScalarImage rounded = linearCopy(hdr, 220);
  for (float& v : rounded.values) v = std::round(v);
  EXPECT_GT(structuralFidelity(hdr, rounded).structuralFidelity, 0.9999);
}

TEST(Tmqi, FidelityDoesNotDependOnTheHdrUnit) {
  const ScalarImage hdr = texturedLuminance();
  ScalarImage scaled = hdr;
  for (float& v : scaled.values) v = v * 1000 + 5;  // another unit, another black
  const ScalarImage ldr = withNoise(linearCopy(hdr, 220), 10, 3);
  EXPECT_NEAR(structuralFidelity(scaled, ldr).structuralFidelity,
              structuralFidelity(hdr, ldr).structuralFidelity, 1e-6);
}

TEST(Tmqi, ContrastTheDisplayMakesInvisibleCostsFidelity) {
  // The same structure squeezed into 3 of 255 levels: local deviations below the visibility
  // threshold (about 1-3 levels, by scale), which the HDR reference shows.
  const ScalarImage hdr = texturedLuminance();
  ScalarImage faint = linearCopy(hdr, 220);
  for (float& v : faint.values) v = 120 + v / 85;
  EXPECT_LT(structuralFidelity(hdr, faint).structuralFidelity, 0.1);  // 0.018 measured
}

TEST(Tmqi, NoiseLowersFidelityStepByStep) {
  const ScalarImage hdr = texturedLuminance();
  const ScalarImage ldr = linearCopy(hdr, 220);
  double previous = structuralFidelity(hdr, ldr).structuralFidelity;
  for (double sigma : {2.0, 5.0, 10.0, 20.0, 40.0}) {
    const double s = structuralFidelity(hdr, withNoise(ldr, sigma, 7)).structuralFidelity;
    EXPECT_LT(s, previous) << "noise sigma " << sigma;
    previous = s;
  }
  EXPECT_LT(previous, 0.8);  // 0.73 at sigma 40: the steps are not rounding
}

TEST(Tmqi, BlurLowersFidelityStepByStep) {
  const ScalarImage hdr = texturedLuminance();
  const ScalarImage ldr = linearCopy(hdr, 220);
  double previous = structuralFidelity(hdr, ldr).structuralFidelity;
  for (int radius : {1, 2, 3, 4, 6}) {
    const double s = structuralFidelity(hdr, boxBlurred(ldr, radius)).structuralFidelity;
    EXPECT_LT(s, previous) << "box blur radius " << radius;
    previous = s;
  }
  EXPECT_LT(previous, 0.8);  // 0.73 at radius 6
}

TEST(Tmqi, MidGreyIsMoreNaturalThanAlmostBlack) {
  const ScalarImage hdr = texturedLuminance();
  const double midGrey = statisticalNaturalness(linearCopy(hdr, 220));
  const double almostBlack = statisticalNaturalness(linearCopy(hdr, 5000));
  EXPECT_GT(midGrey, 0.5);
  EXPECT_LT(almostBlack, 0.01);
  EXPECT_GT(midGrey, almostBlack);
}

// The Beta(α, β) density from its definition, with the Beta function from lgamma.
double betaDensity(double x, double alpha, double beta) {
  const double logB = std::lgamma(alpha) + std::lgamma(beta) - std::lgamma(alpha + beta);
  return std::exp((alpha - 1) * std::log(x) + (beta - 1) * std::log(1 - x) - logB);
}

TEST(Tmqi, NaturalnessIsTheProductOfTheTwoFittedDensities) {
  // Columns 40 + 9·(x mod 11) on 176 × 176: every 11 × 11 block holds each of 0 … 10 eleven
  // times, so its mean is 85 and its sample standard deviation 9·√(10 · 121 / 120).
  ScalarImage image(176, 176);
  for (int y = 0; y < 176; ++y) {
    for (int x = 0; x < 176; ++x) image.at(x, y) = static_cast<float>(40 + 9 * (x % 11));
  }
  const double mean = 85, deviation = 9 * std::sqrt(10.0 * 121 / 120);
  const double alpha = 4.4, beta = 10.1, mode = (alpha - 1) / (alpha + beta - 2);
  const double brightness = std::exp(-std::pow((mean - 115.94) / 27.99, 2) / 2);
  const double contrast =
      betaDensity(deviation / 64.29, alpha, beta) / betaDensity(mode, alpha, beta);
  EXPECT_NEAR(statisticalNaturalness(image), brightness * contrast, 1e-9);
  const NaturalnessFactors factors = naturalnessFactors(image);
  EXPECT_NEAR(factors.meanLuma, mean, 1e-9);
  EXPECT_NEAR(factors.blockDeviation, deviation, 1e-9);
  EXPECT_NEAR(factors.brightness, brightness, 1e-9);
  EXPECT_NEAR(factors.contrast, contrast, 1e-9);
}

TEST(Tmqi, QualityCombinesFidelityAndNaturalness) {
  const ScalarImage hdr = texturedLuminance();
  const ScalarImage ldr = withNoise(linearCopy(hdr, 400), 8, 5);
  const TmqiScore score = toneMappedQuality(hdr, ldr);
  EXPECT_DOUBLE_EQ(score.structuralFidelity, structuralFidelity(hdr, ldr).structuralFidelity);
  EXPECT_DOUBLE_EQ(score.naturalness, statisticalNaturalness(ldr));
  EXPECT_NEAR(score.quality,
              0.8012 * std::pow(score.structuralFidelity, 0.3046) +
                  0.1988 * std::pow(score.naturalness, 0.7088),
              1e-12);
}

TEST(Tmqi, RejectsImagesTooSmallForFiveScales) {
  const ScalarImage small(160, 300), fits(161, 161);
  EXPECT_THROW(structuralFidelity(small, small), std::invalid_argument);
  ScalarImage ramp = fits;
  for (size_t i = 0; i < ramp.values.size(); ++i) ramp.values[i] = static_cast<float>(i % 161);
  EXPECT_NO_THROW(structuralFidelity(ramp, ramp));
  EXPECT_THROW(structuralFidelity(ramp, ScalarImage(161, 162)), std::invalid_argument);
  EXPECT_THROW(structuralFidelity(fits, fits), std::invalid_argument);  // a flat reference
}

}  // namespace
}  // namespace penumbra
