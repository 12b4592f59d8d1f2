#include "tonemap/tmqi.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace penumbra {
namespace {

// Q = a S^α + (1 - a) N^β.
constexpr double kFidelityShare = 0.8012, kFidelityExponent = 0.3046, kNaturalnessExponent = 0.7088;
// Scale weights, finest first; spatial frequency 16, 8, 4, 2, 1 cycles/degree.
constexpr std::array<double, kTmqiScales> kScaleWeight = {0.0448, 0.2856, 0.3001, 0.2363, 0.1333};
constexpr double kFinestFrequency = 16;
// Local window: 11×11 Gaussian, σ = 1.5 pixels, normalised.
constexpr int kWindow = 11;
constexpr double kWindowSigma = 1.5;
// Stabilising constants of the local term.
constexpr double kC1 = 0.01, kC2 = 10;
// Naturalness: brightness ~ Gaussian(115.94, 27.99); contrast (mean block std / 64.29) ~
// Beta(4.4, 10.1); each divided by its peak. Blocks are 11×11.
constexpr double kMeanCentre = 115.94, kMeanSpread = 27.99;
constexpr double kContrastScale = 64.29, kContrastAlpha = 4.4, kContrastBeta = 10.1;
constexpr int kBlock = 11;
// The HDR image is scaled linearly to [0, 2^32 - 1].
constexpr double kHdrRange = 4294967295.0;

struct LuminancePlane {
  int width = 0, height = 0;
  std::vector<double> v;
  double at(int x, int y) const { return v[static_cast<size_t>(y) * width + x]; }
};

LuminancePlane planeOf(const ScalarImage& image, double offset, double scale) {
  LuminancePlane p{image.width, image.height, std::vector<double>(image.values.size())};
  for (size_t i = 0; i < p.v.size(); ++i) p.v[i] = (image.values[i] - offset) * scale;
  return p;
}

// The next coarser scale: the mean of each 2×2 block starting at even coordinates; a last odd
// row or column is mirrored onto itself (MATLAB's symmetric border), so the size halves rounding
// up.
LuminancePlane halve(const LuminancePlane& p) {
  LuminancePlane h{(p.width + 1) / 2, (p.height + 1) / 2, {}};
  h.v.resize(static_cast<size_t>(h.width) * h.height);
  for (int y = 0; y < h.height; ++y) {
    const int y0 = 2 * y, y1 = std::min(2 * y + 1, p.height - 1);
    for (int x = 0; x < h.width; ++x) {
      const int x0 = 2 * x, x1 = std::min(2 * x + 1, p.width - 1);
      h.v[static_cast<size_t>(y) * h.width + x] =
          0.25 * (p.at(x0, y0) + p.at(x1, y0) + p.at(x0, y1) + p.at(x1, y1));
    }
  }
  return h;
}

std::array<double, kWindow * kWindow> gaussianWindow() {
  std::array<double, kWindow * kWindow> w{};
  double sum = 0;
  for (int j = 0; j < kWindow; ++j) {
    for (int i = 0; i < kWindow; ++i) {
      const double dx = i - kWindow / 2, dy = j - kWindow / 2;
      w[j * kWindow + i] = std::exp(-(dx * dx + dy * dy) / (2 * kWindowSigma * kWindowSigma));
      sum += w[j * kWindow + i];
    }
  }
  for (double& value : w) value /= sum;
  return w;
}

double normalCdf(double x, double mean, double sigma) {
  return 0.5 * std::erfc(-(x - mean) / (sigma * std::sqrt(2.0)));
}

// The mean over every window position inside the image (no border) of
//   (2 σ̃₁σ̃₂ + C1) / (σ̃₁² + σ̃₂² + C1) · (σ₁₂ + C2) / (σ₁σ₂ + C2)
// where σ̃ = Φ(σ; τ, τ/3) is the probability that a local standard deviation σ is seen, τ the
// visibility threshold from the Mannos-Sakrison contrast sensitivity at `frequency` cycles/degree.
// Moments are computed about each window's own mean (two passes), exact also at 2^32 scale.
double localFidelity(const LuminancePlane& hdr, const LuminancePlane& ldr, double frequency) {
  const auto window = gaussianWindow();
  const double sensitivity =
      100 * 2.6 * (0.0192 + 0.114 * frequency) * std::exp(-std::pow(0.114 * frequency, 1.1));
  const double threshold = 128 / (1.4 * sensitivity), spread = threshold / 3;
  const int outW = hdr.width - kWindow + 1, outH = hdr.height - kWindow + 1;
  std::vector<double> rowSums(outH, 0.0);
  tbb::parallel_for(0, outH, [&](int y) {
    double rowSum = 0;
    for (int x = 0; x < outW; ++x) {
      double mean1 = 0, mean2 = 0;
      for (int j = 0; j < kWindow; ++j) {
        for (int i = 0; i < kWindow; ++i) {
          const double w = window[j * kWindow + i];
          mean1 += w * hdr.at(x + i, y + j);
          mean2 += w * ldr.at(x + i, y + j);
        }
      }
      double var1 = 0, var2 = 0, cov = 0;
      for (int j = 0; j < kWindow; ++j) {
        for (int i = 0; i < kWindow; ++i) {
          const double w = window[j * kWindow + i];
          const double d1 = hdr.at(x + i, y + j) - mean1, d2 = ldr.at(x + i, y + j) - mean2;
          var1 += w * d1 * d1, var2 += w * d2 * d2, cov += w * d1 * d2;
        }
      }
      const double sigma1 = std::sqrt(var1), sigma2 = std::sqrt(var2);
      const double seen1 = normalCdf(sigma1, threshold, spread);
      const double seen2 = normalCdf(sigma2, threshold, spread);
      rowSum += (2 * seen1 * seen2 + kC1) / (seen1 * seen1 + seen2 * seen2 + kC1) * (cov + kC2) /
                (sigma1 * sigma2 + kC2);
    }
    rowSums[y] = rowSum;
  });
  double sum = 0;
  for (double s : rowSums) sum += s;
  return sum / (double(outW) * outH);
}

void checkSizes(const ScalarImage& hdr, const ScalarImage& ldr) {
  if (hdr.width != ldr.width || hdr.height != ldr.height) {
    throw std::invalid_argument("TMQI: the HDR and display images differ in size");
  }
  int w = hdr.width, h = hdr.height;
  for (int scale = 1; scale < kTmqiScales; ++scale) w = (w + 1) / 2, h = (h + 1) / 2;
  if (w < kWindow || h < kWindow) {
    throw std::invalid_argument(
        "TMQI: the image is too small for five scales of an 11-pixel "
        "window (at least 161 pixels each way)");
  }
}

}  // namespace

TmqiScore structuralFidelity(const ScalarImage& hdrLuminance, const ScalarImage& displayLuminance) {
  checkSizes(hdrLuminance, displayLuminance);
  const auto [low, high] =
      std::minmax_element(hdrLuminance.values.begin(), hdrLuminance.values.end());
  if (!(*high > *low)) throw std::invalid_argument("TMQI: the HDR image is flat");
  LuminancePlane hdr = planeOf(hdrLuminance, *low, kHdrRange / (double(*high) - *low));
  LuminancePlane ldr = planeOf(displayLuminance, 0, 1);
  TmqiScore score;
  score.structuralFidelity = 1;
  double frequency = kFinestFrequency;
  for (int scale = 0; scale < kTmqiScales; ++scale) {
    const double s = localFidelity(hdr, ldr, frequency);
    score.scaleFidelity[scale] = s;
    // An anti-correlated scale (s < 0) has no real power; it counts as no fidelity.
    score.structuralFidelity *= std::pow(std::max(s, 0.0), kScaleWeight[scale]);
    if (scale + 1 < kTmqiScales) hdr = halve(hdr), ldr = halve(ldr), frequency /= 2;
  }
  return score;
}

NaturalnessFactors naturalnessFactors(const ScalarImage& displayLuminance) {
  const int width = displayLuminance.width, height = displayLuminance.height;
  if (width < 1 || height < 1) throw std::invalid_argument("TMQI: empty display image");
  double total = 0, deviationSum = 0;
  // Each 11×11 block (tiled from the top left; the last ones hold only the image's own pixels)
  // gives its sample standard deviation to each of its pixels; the image's mean of that.
  for (int by = 0; by < height; by += kBlock) {
    for (int bx = 0; bx < width; bx += kBlock) {
      double sum = 0, sumSq = 0;
      int n = 0;
      for (int y = by; y < std::min(by + kBlock, height); ++y) {
        for (int x = bx; x < std::min(bx + kBlock, width); ++x) {
          const double v = displayLuminance.at(x, y);
          sum += v, sumSq += v * v, ++n;
        }
      }
      const double mean = sum / n;
      const double variance = n > 1 ? std::max(0.0, (sumSq - n * mean * mean) / (n - 1)) : 0.0;
      total += sum;
      deviationSum += n * std::sqrt(variance);
    }
  }
  const double pixels = double(width) * height;
  NaturalnessFactors factors;
  factors.meanLuma = total / pixels;
  factors.blockDeviation = deviationSum / pixels;
  const double mean = factors.meanLuma, contrast = factors.blockDeviation / kContrastScale;
  factors.brightness =
      std::exp(-(mean - kMeanCentre) * (mean - kMeanCentre) / (2 * kMeanSpread * kMeanSpread));
  // Beta(α, β) density over its value at the mode m = (α - 1) / (α + β - 2).
  const double mode = (kContrastAlpha - 1) / (kContrastAlpha + kContrastBeta - 2);
  factors.contrast = contrast > 0 && contrast < 1
                         ? std::pow(contrast / mode, kContrastAlpha - 1) *
                               std::pow((1 - contrast) / (1 - mode), kContrastBeta - 1)
                         : 0.0;
  return factors;
}

double statisticalNaturalness(const ScalarImage& displayLuminance) {
  const NaturalnessFactors factors = naturalnessFactors(displayLuminance);
  return factors.brightness * factors.contrast;
}

TmqiScore toneMappedQuality(const ScalarImage& hdrLuminance, const ScalarImage& displayLuminance) {
  TmqiScore score = structuralFidelity(hdrLuminance, displayLuminance);
  score.naturalnessFactors = naturalnessFactors(displayLuminance);
  score.naturalness = score.naturalnessFactors.brightness * score.naturalnessFactors.contrast;
  score.quality = kFidelityShare * std::pow(score.structuralFidelity, kFidelityExponent) +
                  (1 - kFidelityShare) * std::pow(score.naturalness, kNaturalnessExponent);
  return score;
}

ScalarImage luminanceOf(const RgbImage& rgb) {
  ScalarImage y(rgb.width, rgb.height);
  for (size_t i = 0; i < y.values.size(); ++i) {
    const float* p = &rgb.rgb[i * 3];
    y.values[i] = static_cast<float>(0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]);
  }
  return y;
}

ScalarImage lumaOf(const DisplayImage& image) {
  ScalarImage y(image.width, image.height);
  const int c = image.channels;
  for (size_t i = 0; i < y.values.size(); ++i) {
    const uint8_t* p = &image.values[i * c];
    y.values[i] = c >= 3 ? static_cast<float>(0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2])
                         : static_cast<float>(p[0]);
  }
  return y;
}

}  // namespace penumbra
