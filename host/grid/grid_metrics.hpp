#pragma once
// The figures a lighting designer reads off a calculation grid (EN 12464-1 style): average,
// minimum and maximum illuminance and the two uniformities.
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

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

// The daylight factor over a grid's points not inside solids (docs/method.md, "Daylight
// factor"): DF = 100 · E / E_h %, E the illuminance at the point (total, or its direct part) and
// E_h the sky's unobstructed horizontal illuminance outdoors.
inline constexpr double kDaylightFactorTargets[] = {1.0, 2.0, 3.0, 5.0};  // %

// EN 17037 daylight provision through the daylight factor (its method for side-lit spaces, the
// grid being the reference plane): a level is met when DF >= D_T on at least 50 % of the plane
// and DF >= D_TM on at least 95 % of it, D = 100 · E / E_v,d,med % for the level's target
// illuminance E_T and minimum target illuminance E_TM, E_v,d,med the site's median external
// diffuse illuminance.
struct DaylightProvisionLevel {
  std::string_view name;
  double targetIlluminance = 0.0;         // lx: E_T, on 50 % of the reference plane
  double minimumTargetIlluminance = 0.0;  // lx: E_TM, on 95 % of it
};
inline constexpr DaylightProvisionLevel kDaylightProvisionLevels[] = {
    {"minimum", 300.0, 100.0}, {"medium", 500.0, 300.0}, {"high", 750.0, 500.0}};
inline constexpr double kTargetShare = 0.5;          // of the reference plane, for D_T
inline constexpr double kMinimumTargetShare = 0.95;  // for D_TM

struct DaylightProvisionCheck {
  double target = 0.0, minimumTarget = 0.0;  // %: D_T, D_TM
  // Shares of the points with DF >= D_T and DF >= D_TM, in [0, 1]; NaN when no point counts.
  double shareTarget = 0.0, shareMinimumTarget = 0.0;
  bool met = false;
};

struct DaylightProvision {
  double medianDiffuseIlluminance = 0.0;       // lx: E_v,d,med
  std::vector<DaylightProvisionCheck> levels;  // per kDaylightProvisionLevels entry
  // The highest level met ("minimum", "medium", "high"), or "none".
  std::string_view reached() const;
};

// The mean daylight factor split into the BRE components (docs/method.md, "Daylight factor
// components"), %: they add up to DaylightMetrics::mean.
struct DaylightComponents {
  double sky = 0.0;                  // SC: the sky seen through the openings, direct
  double externallyReflected = 0.0;  // ERC: the ground through the openings, the obstructions
  double internallyReflected = 0.0;  // IRC: the room's faces, the rest of the mean
};

struct DaylightMetrics {
  double outdoorIlluminance = 0.0;                        // lx: E_h
  double mean = 0.0, median = 0.0, min = 0.0, max = 0.0;  // %; NaN when no point counts
  double uniformity = 0.0;                                // min / mean; NaN when the mean is 0
  // Per kDaylightFactorTargets entry: the share of the points with DF >= the target, in [0, 1].
  std::vector<double> shareAtLeast;
  double directMean = 0.0;    // %: the mean DF of the direct part (sky and ground through the
                              // openings); the mean itself for a direct-only run
  double internalMean = 0.0;  // %: mean − directMean, the internally reflected component
  // With interreflection: the mean's components.
  std::optional<DaylightComponents> components;
  std::optional<DaylightProvision> provision;  // when the site gives E_v,d,med
  // Whether the grid faces up, a horizontal reference plane: EN 17037 judges no other.
  bool horizontal = true;
};

// The direct sunlight on a grid's points not inside solids (illuminance/sunlight.hpp).
struct SunMetrics {
  double eAvg = 0.0, eMax = 0.0;  // lx; NaN when no point counts
  double sunlitShare = 0.0;       // of the points with E_sun > 0, in [0, 1]; NaN when none counts
};

// The metrics of E_sun added point by point.
class SunMetricsSum {
 public:
  void add(double sun, bool insideSolid);
  SunMetrics metrics() const;

 private:
  std::size_t counted_ = 0, sunlit_ = 0;
  double sum_ = 0.0, max_ = 0.0;
};

// From E (lx) of the points not inside solids, and of its direct part (empty: direct only);
// the EN 17037 provision when `medianDiffuseIlluminance` (lx, E_v,d,med) is given.
DaylightMetrics daylightMetrics(std::vector<double> illuminance, std::span<const double> direct,
                                double outdoorIlluminance,
                                std::optional<double> medianDiffuseIlluminance = std::nullopt);

// The same from DF (%) of the points not inside solids and of its direct part (empty: direct
// only), as a grid's CSV holds them; E_h (lx) is kept in the result for the record.
DaylightMetrics daylightFactorMetrics(std::vector<double> factors, std::span<const double> direct,
                                      double outdoorIlluminance,
                                      std::optional<double> medianDiffuseIlluminance);

// The components of `metrics`' mean from the means of the sky and the externally reflected
// components (%); IRC is the rest of the mean.
DaylightComponents daylightComponents(const DaylightMetrics& metrics, double skyMean,
                                      double externalMean);

// `inside[i]` is the index of the solid that strictly contains point i, -1 for none.
GridMetrics gridMetrics(std::span<const double> illuminance, std::span<const int> inside,
                        double spacing);

}  // namespace penumbra
