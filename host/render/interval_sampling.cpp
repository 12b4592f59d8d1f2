#include "render/interval_sampling.hpp"

#include <algorithm>

namespace penumbra {

IntervalPlan::IntervalPlan(int width, int height, std::span<const uint32_t> faceIds,
                           std::span<const uint8_t> needed, int interval) {
  const int k = std::max(interval, 1);
  for (int y = 0; y < height; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * width;
    for (int a = 0; a < width; a += k) {
      const int b = std::min(a + k, width - 1);
      if (needed[row + a]) first_.push_back(row + a);
      if (b <= a) break;  // the last sample of the row was this interval's start
      // Interpolation needs both ends on the same face and nothing else in between.
      bool uniform = needed[row + a] != 0;
      for (int x = a + 1; x <= b && uniform; ++x) uniform = faceIds[row + x] == faceIds[row + a];
      if (uniform && b - a >= 2) {
        undecided_.push_back(Interval{row + a, row + b});
      } else {
        for (int x = a + 1; x < b; ++x)
          if (needed[row + x]) first_.push_back(row + x);
      }
      if (b == width - 1) {
        if (needed[row + b]) first_.push_back(row + b);
        break;
      }
    }
  }
}

std::vector<std::size_t> IntervalPlan::secondPass(
    const std::function<bool(std::size_t a, std::size_t b)>& sameClasses) {
  std::vector<std::size_t> second;
  for (const Interval& interval : undecided_) {
    if (sameClasses(interval.a, interval.b)) {
      interpolated_.push_back(interval);
    } else {
      for (std::size_t i = interval.a + 1; i < interval.b; ++i) second.push_back(i);
    }
  }
  undecided_.clear();
  return second;
}

void IntervalPlan::interpolate(std::span<float> values, int channels) const {
  for (const Interval& interval : interpolated_) {
    const double length = static_cast<double>(interval.b - interval.a);
    for (std::size_t i = interval.a + 1; i < interval.b; ++i) {
      const double t = (i - interval.a) / length;
      for (int c = 0; c < channels; ++c) {
        const double va = values[interval.a * channels + c];
        const double vb = values[interval.b * channels + c];
        values[i * channels + c] = static_cast<float>(va + t * (vb - va));
      }
    }
  }
}

}  // namespace penumbra
