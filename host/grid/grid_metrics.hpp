#pragma once
// The figures a lighting designer reads off a calculation grid (EN 12464-1 style): average,
// minimum and maximum illuminance and the two uniformities.
#include <cstddef>
#include <limits>
#include <span>

namespace penumbra {

struct GridMetrics {
  std::size_t points = 0;              // every point of the grid
  std::size_t pointsInsideSolids = 0;  // left out of every statistic below
  double spacing = 0.0;                // m; 0 for point lists
  // Over the points not inside solids; NaN when there are none.
  double eAvg = 0.0;  // lx
  double eMin = 0.0;  // lx
  double eMax = 0.0;  // lx
  double u0 = 0.0;    // Emin / Eavg; NaN when Eavg = 0
  double ud = 0.0;    // Emin / Emax; NaN when Emax = 0
};

// The metrics of values added one by one, in the grid's order (the sums, and so the metrics, are
// the same as gridMetrics' over the whole arrays).
class GridMetricsSum {
 public:
  void add(double illuminance, bool insideSolid);
  GridMetrics metrics(double spacing) const;

 private:
  std::size_t points_ = 0, inside_ = 0, counted_ = 0;
  double sum_ = 0.0;
  double lo_ = std::numeric_limits<double>::infinity();
  double hi_ = -std::numeric_limits<double>::infinity();
};

// `inside[i]` is the index of the solid that strictly contains point i, -1 for none.
GridMetrics gridMetrics(std::span<const double> illuminance, std::span<const int> inside,
                        double spacing);

}  // namespace penumbra
