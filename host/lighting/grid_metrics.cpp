#include "lighting/grid_metrics.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace penumbra {

GridMetrics gridMetrics(std::span<const double> illuminance, std::span<const int> inside,
                        double spacing) {
  if (illuminance.size() != inside.size()) {
    throw std::invalid_argument("gridMetrics: one `inside` entry per point is needed");
  }
  GridMetrics m;
  m.points = illuminance.size();
  m.spacing = spacing;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  std::size_t counted = 0;
  for (std::size_t i = 0; i < illuminance.size(); ++i) {
    // A point inside a solid is not on any surface a person could see: it would drag Emin to 0.
    if (inside[i] >= 0) {
      ++m.pointsInsideSolids;
      continue;
    }
    sum += illuminance[i];
    lo = std::min(lo, illuminance[i]);
    hi = std::max(hi, illuminance[i]);
    ++counted;
  }
  if (counted == 0) {
    m.eAvg = m.eMin = m.eMax = m.u0 = m.ud = nan;
    return m;
  }
  m.eAvg = sum / static_cast<double>(counted);
  m.eMin = lo;
  m.eMax = hi;
  m.u0 = m.eAvg > 0.0 ? m.eMin / m.eAvg : nan;
  m.ud = m.eMax > 0.0 ? m.eMin / m.eMax : nan;
  return m;
}

}  // namespace penumbra
