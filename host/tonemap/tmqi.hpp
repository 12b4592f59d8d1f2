#pragma once
// The tone-mapped image quality index (TMQI) of Yeganeh & Wang, "Objective Quality Assessment of
// Tone-Mapped Images", IEEE TIP 22(2), 2013: how well a display image (LDR) keeps the structure
// of the HDR image it was made from (structural fidelity S) and how natural it looks (statistical
// naturalness N), combined into Q = a S^α + (1 - a) N^β. A full-reference measure: the HDR image
// is the reference, the display image is judged. Constants and choices: docs/tonemap.md, "TMQI".
#include <array>

#include "image/images.hpp"

namespace penumbra {

inline constexpr int kTmqiScales = 5;

// What N is made of: the display image's two statistics and their likelihoods under the
// distributions fitted to natural images, each divided by its peak (N = brightness · contrast).
struct NaturalnessFactors {
  double meanLuma = 0;        // the image's mean luma, 0-255
  double blockDeviation = 0;  // its mean 11×11-block sample standard deviation, luma levels
  double brightness = 0;      // Gaussian likelihood of meanLuma (peak at 115.94)
  double contrast = 0;        // Beta likelihood of blockDeviation / 64.29 (peak at 17.5 levels)
};

struct TmqiScore {
  double structuralFidelity = 0;  // S in [0, 1]: Π S_l^w_l over the scales
  double naturalness = 0;         // N in [0, 1]: brightness and contrast likelihoods, each ≤ 1
  NaturalnessFactors naturalnessFactors;
  double quality = 0;                               // Q = a S^α + (1 - a) N^β
  std::array<double, kTmqiScales> scaleFidelity{};  // S_l, finest scale first
};

// hdrLuminance: the reference, in any linear unit (cd/m²); it is scaled linearly to
// [0, 2^32 - 1] as the authors do. displayLuminance: the display image's luma in [0, 255] (the
// 8-bit values as they are, no transfer curve removed), the unit N's statistics were fitted in.
// Both the same size, at least 161 pixels on each side (the fifth scale, 1/16 of the size, must
// hold the 11-pixel window). Throws std::invalid_argument otherwise, or when the HDR image is flat.
TmqiScore toneMappedQuality(const ScalarImage& hdrLuminance, const ScalarImage& displayLuminance);

// S and its per-scale terms alone (Q and N left 0).
TmqiScore structuralFidelity(const ScalarImage& hdrLuminance, const ScalarImage& displayLuminance);

// N alone: the display image's mean and its mean 11×11-block standard deviation against the
// distributions fitted to natural images.
double statisticalNaturalness(const ScalarImage& displayLuminance);
// The same, factor by factor.
NaturalnessFactors naturalnessFactors(const ScalarImage& displayLuminance);

// Luminance Y (Rec. 709 / sRGB primaries: 0.2126 R + 0.7152 G + 0.0722 B) of linear RGB.
ScalarImage luminanceOf(const RgbImage& rgb);
// The same weights on 8-bit values, in [0, 255]: the luma TMQI reads from a display image.
ScalarImage lumaOf(const DisplayImage& image);

}  // namespace penumbra
