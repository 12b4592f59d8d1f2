#pragma once
// The median of a bench's repeated timings: steadier than the mean on a shared machine, where a
// run now and then meets another load.
#include <algorithm>
#include <limits>
#include <vector>

namespace penumbra::bench {

// The middle value, or the mean of the two middle ones for an even count; NaN for none.
inline double median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

}  // namespace penumbra::bench
