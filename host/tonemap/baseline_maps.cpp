#include "tonemap/baseline_maps.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra {

ScalarImage linearDisplayValues(const DisplaySpaces& spaces) {
  ScalarImage display(spaces.width, spaces.height);
  for (size_t i = 0; i < spaces.value3.size(); ++i) {
    display.values[i] = boundedDisplayValue(spaces.value3[i], spaces.lowerBound);
  }
  return display;
}

double automaticWhite(const DisplaySpaces& spaces, const RegionMap& regions) {
  // Log average over lit surface pixels; 1e-4 of the brightest keeps an umbra (V = 0) from
  // dragging the average to zero.
  const double floor = std::max(spaces.maxRgb, 1e-30) * 1e-4;
  double logSum = 0;
  size_t counted = 0;
  for (size_t i = 0; i < spaces.value0.size(); ++i) {
    if (regions.region[i] == RegionMap::kNone && regions.count > 0) continue;
    logSum += std::log(std::max<double>(spaces.value0[i], floor));
    ++counted;
  }
  const double average = counted ? std::exp(logSum / counted) : 1.0;
  return average / 0.18;
}

ScalarImage clipDisplayValues(const DisplaySpaces& spaces, double white) {
  const double exposure = 1.0 / white;
  ScalarImage display(spaces.width, spaces.height);
  for (size_t i = 0; i < spaces.value0.size(); ++i) {
    display.values[i] = boundedDisplayValue(exposure * spaces.value0[i], spaces.lowerBound);
  }
  return display;
}

}  // namespace penumbra
