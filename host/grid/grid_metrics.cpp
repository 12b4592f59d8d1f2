#include "grid/grid_metrics.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace penumbra {

void GridMetricsSum::add(double illuminance, bool insideSolid) {
  ++points_;
  // A point inside a solid is not on any surface a person could see: it would drag Emin to 0.
  if (insideSolid) {
    ++inside_;
    return;
  }
  sum_ += illuminance;
  lo_ = std::min(lo_, illuminance);
  hi_ = std::max(hi_, illuminance);
  ++counted_;
}

GridMetrics GridMetricsSum::metrics(double spacing) const {
  GridMetrics m;
  m.points = points_;
  m.pointsInsideSolids = inside_;
  m.spacing = spacing;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (counted_ == 0) {
    m.eAvg = m.eMin = m.eMax = m.u0 = m.ud = nan;
    return m;
  }
  m.eAvg = sum_ / static_cast<double>(counted_);
  m.eMin = lo_;
  m.eMax = hi_;
  m.u0 = m.eAvg > 0.0 ? m.eMin / m.eAvg : nan;
  m.ud = m.eMax > 0.0 ? m.eMin / m.eMax : nan;
  return m;
}

GridMetrics gridMetrics(std::span<const double> illuminance, std::span<const int> inside,
                        double spacing) {
  if (illuminance.size() != inside.size()) {
    throw std::invalid_argument("gridMetrics: one `inside` entry per point is needed");
  }
  GridMetricsSum sums;
  for (std::size_t i = 0; i < illuminance.size(); ++i) sums.add(illuminance[i], inside[i] >= 0);
  return sums.metrics(spacing);
}

}  // namespace penumbra
