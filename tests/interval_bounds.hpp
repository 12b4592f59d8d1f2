#pragma once
// What interval mode promises (docs/render.md), measured on what the picture shows, the luminance
// Y of the RGB image (luminanceOf: Rec. 709 weights, cd/m²): within 0.5 % of the 99th percentile of
// the exact (k = 1) image at every pixel, and within 1 % of its own value at every pixel above 1 %
// of that percentile.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "render/renderer.hpp"
#include "tonemap/tmqi.hpp"

namespace penumbra::testing {

struct IntervalErrors {
  double p99 = 0.0;            // cd/m², of the exact image
  double worst = 0.0;          // cd/m², the largest |Y_k − Y_1|
  double worstRelative = 0.0;  // the largest |Y_k − Y_1| / Y_1 above 1 % of p99
  std::size_t bright = 0;      // pixels above 1 % of p99
  std::size_t pixels = 0;
};

inline IntervalErrors intervalErrors(const RenderedView& exact, const RenderedView& sampled) {
  IntervalErrors e;
  const std::vector<float> y1 = luminanceOf(exact.luminance).values,
                           yk = luminanceOf(sampled.luminance).values;
  e.pixels = y1.size();
  if (e.pixels == 0) return e;
  std::vector<float> sorted = y1;
  const std::size_t at = static_cast<std::size_t>(0.99 * static_cast<double>(e.pixels - 1));
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(at), sorted.end());
  e.p99 = sorted[at];
  for (std::size_t i = 0; i < e.pixels; ++i) {
    const double error = std::abs(double(yk[i]) - y1[i]);
    e.worst = std::max(e.worst, error);
    if (y1[i] > 0.01 * e.p99) {
      ++e.bright;
      e.worstRelative = std::max(e.worstRelative, error / y1[i]);
    }
  }
  return e;
}

}  // namespace penumbra::testing
