#include "render/interval_sampling.hpp"

#include <algorithm>
#include <cmath>

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

void IntervalPlan::appendInterior(const Interval& interval, std::vector<std::size_t>& out) {
  for (std::size_t i = interval.a + 1; i < interval.b; ++i) out.push_back(i);
}

std::vector<std::size_t> IntervalPlan::secondPass(std::span<const ShadowClass> classes,
                                                  int sources) {
  std::vector<std::size_t> next;
  for (const Interval& interval : undecided_) {
    bool same = true, penumbra = false;
    for (int s = 0; s < sources; ++s) {
      const ShadowClass ca = classes[interval.a * sources + s];
      same &= ca == classes[interval.b * sources + s];
      penumbra |= ca == ShadowClass::Penumbra;
    }
    if (!same) {
      appendInterior(interval, next);
    } else if (penumbra && interval.b - interval.a >= 3) {
      next.push_back((interval.a + interval.b) / 2);
      checking_.push_back(interval);
    } else {
      // Lit or umbra throughout (or a single inner sample: interpolating it from its two
      // neighbours costs as much to check as to compute, so compute it).
      if (penumbra) {
        appendInterior(interval, next);
      } else {
        interpolated_.push_back(interval);
      }
    }
  }
  undecided_.clear();
  return next;
}

std::vector<std::size_t> IntervalPlan::thirdPass(std::span<const float> illuminance) {
  std::vector<std::size_t> next;
  for (const Interval& interval : checking_) {
    const std::size_t m = (interval.a + interval.b) / 2;
    const double ea = illuminance[interval.a], eb = illuminance[interval.b], em = illuminance[m];
    const double t = static_cast<double>(m - interval.a) / (interval.b - interval.a);
    const double line = ea + t * (eb - ea);
    const double scale = std::max({std::abs(ea), std::abs(eb), std::abs(em)});
    if (std::abs(em - line) <= kPenumbraLinearity * scale) {
      interpolated_.push_back(Interval{interval.a, m});
      interpolated_.push_back(Interval{m, interval.b});
    } else {
      for (std::size_t i = interval.a + 1; i < interval.b; ++i)
        if (i != m) next.push_back(i);
    }
  }
  checking_.clear();
  return next;
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
