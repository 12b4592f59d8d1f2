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

void SunMetricsSum::add(double sun, bool insideSolid) {
  if (insideSolid) return;
  ++counted_;
  sum_ += sun;
  max_ = std::max(max_, sun);
  if (sun > 0.0) ++sunlit_;
}

SunMetrics SunMetricsSum::metrics() const {
  SunMetrics m;
  if (counted_ == 0) {
    m.eAvg = m.eMax = m.sunlitShare = std::numeric_limits<double>::quiet_NaN();
    return m;
  }
  const auto n = static_cast<double>(counted_);
  m.eAvg = sum_ / n;
  m.eMax = max_;
  m.sunlitShare = static_cast<double>(sunlit_) / n;
  return m;
}

namespace {

// The share of `sorted` (E in lx, ascending) with DF = 100 · E / E_h >= `df` (%), in [0, 1].
double shareAtLeast(const std::vector<double>& sorted, double df, double outdoorIlluminance) {
  if (sorted.empty()) return std::numeric_limits<double>::quiet_NaN();
  // DF >= df  <=>  E >= df · E_h / 100.
  const auto below =
      std::lower_bound(sorted.begin(), sorted.end(), df * outdoorIlluminance / 100.0);
  return static_cast<double>(sorted.end() - below) / static_cast<double>(sorted.size());
}

DaylightProvision daylightProvision(const std::vector<double>& sorted, double outdoorIlluminance,
                                    double medianDiffuseIlluminance) {
  DaylightProvision p;
  p.medianDiffuseIlluminance = medianDiffuseIlluminance;
  for (const DaylightProvisionLevel& level : kDaylightProvisionLevels) {
    DaylightProvisionCheck check;
    check.target = 100.0 * level.targetIlluminance / medianDiffuseIlluminance;
    check.minimumTarget = 100.0 * level.minimumTargetIlluminance / medianDiffuseIlluminance;
    check.shareTarget = shareAtLeast(sorted, check.target, outdoorIlluminance);
    check.shareMinimumTarget = shareAtLeast(sorted, check.minimumTarget, outdoorIlluminance);
    check.met =
        check.shareTarget >= kTargetShare && check.shareMinimumTarget >= kMinimumTargetShare;
    p.levels.push_back(check);
  }
  return p;
}

}  // namespace

std::string_view DaylightProvision::reached() const {
  std::string_view best = "none";
  for (std::size_t k = 0; k < levels.size() && k < std::size(kDaylightProvisionLevels); ++k)
    if (levels[k].met) best = kDaylightProvisionLevels[k].name;
  return best;
}

DaylightMetrics daylightMetrics(std::vector<double> illuminance, std::span<const double> direct,
                                double outdoorIlluminance,
                                std::optional<double> medianDiffuseIlluminance) {
  DaylightMetrics m;
  m.outdoorIlluminance = outdoorIlluminance;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double toPercent = 100.0 / outdoorIlluminance;
  const std::size_t n = illuminance.size();
  if (n == 0) {
    m.mean = m.median = m.min = m.max = m.uniformity = m.directMean = m.internalMean = nan;
    m.shareAtLeast.assign(std::size(kDaylightFactorTargets), nan);
    if (medianDiffuseIlluminance)
      m.provision = daylightProvision(illuminance, outdoorIlluminance, *medianDiffuseIlluminance);
    return m;
  }
  double sum = 0.0, directSum = 0.0;
  for (double e : illuminance) sum += e;
  for (double e : direct) directSum += e;
  m.mean = toPercent * sum / static_cast<double>(n);
  m.directMean = direct.empty() ? m.mean : toPercent * directSum / static_cast<double>(n);
  m.internalMean = m.mean - m.directMean;
  std::sort(illuminance.begin(), illuminance.end());
  m.min = toPercent * illuminance.front();
  m.max = toPercent * illuminance.back();
  m.median = toPercent * (n % 2 == 1 ? illuminance[n / 2]
                                     : 0.5 * (illuminance[n / 2 - 1] + illuminance[n / 2]));
  m.uniformity = m.mean > 0.0 ? m.min / m.mean : nan;
  for (double target : kDaylightFactorTargets)
    m.shareAtLeast.push_back(shareAtLeast(illuminance, target, outdoorIlluminance));
  if (medianDiffuseIlluminance)
    m.provision = daylightProvision(illuminance, outdoorIlluminance, *medianDiffuseIlluminance);
  return m;
}

DaylightMetrics daylightFactorMetrics(std::vector<double> factors, std::span<const double> direct,
                                      double outdoorIlluminance,
                                      std::optional<double> medianDiffuseIlluminance) {
  // DF is E in units of E_h / 100: the metrics of E over an outdoor illuminance of 100.
  DaylightMetrics m = daylightMetrics(std::move(factors), direct, 100.0, medianDiffuseIlluminance);
  m.outdoorIlluminance = outdoorIlluminance;
  return m;
}

DaylightComponents daylightComponents(const DaylightMetrics& metrics, double skyMean,
                                      double externalMean) {
  return {skyMean, externalMean, metrics.mean - skyMean - externalMean};
}

}  // namespace penumbra
