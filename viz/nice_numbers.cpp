#include "viz/nice_numbers.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace penumbra::viz {

namespace {

// Comparisons of values computed as m·10^k against data: a relative slack far below anything
// printed, so that 1000 computed as 1·10^3 counts as 1000.
constexpr double kSlack = 1e-12;

double decade(double x) {
  return std::pow(10.0, std::floor(std::log10(x)));
}

}  // namespace

double oneTwoFiveAtLeast(double x) {
  if (!(x > 0.0)) throw std::invalid_argument("oneTwoFiveAtLeast: x must be > 0");
  const double d = decade(x);
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * d >= x * (1.0 - kSlack)) return m * d;
  }
  return 10.0 * d;
}

double oneTwoFiveAtMost(double x) {
  if (!(x > 0.0)) throw std::invalid_argument("oneTwoFiveAtMost: x must be > 0");
  const double d = decade(x);
  for (double m : {10.0, 5.0, 2.0, 1.0}) {
    if (m * d <= x * (1.0 + kSlack)) return m * d;
  }
  return 0.5 * d;
}

std::vector<double> oneTwoFiveBetween(double lo, double hi) {
  std::vector<double> values;
  if (!(hi > lo) || !(hi > 0.0)) return values;
  // From lo (or, when lo is 0, three decades below hi: nobody reads isolux lines of 1/1000 of
  // the peak) up to hi.
  const double start = std::max(lo, hi * 1e-3);
  double d = decade(start);
  for (;; d *= 10.0) {
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * d;
      if (v >= hi * (1.0 - kSlack)) return values;
      if (v > lo * (1.0 + kSlack) && v >= start * (1.0 - kSlack)) values.push_back(v);
    }
  }
}

std::vector<double> multiplesOf(double step, double lo, double hi) {
  std::vector<double> values;
  if (!(step > 0.0)) return values;
  const auto first = static_cast<long long>(std::ceil(lo / step - kSlack * 1e3));
  const auto last = static_cast<long long>(std::floor(hi / step + kSlack * 1e3));
  for (long long k = first; k <= last; ++k) values.push_back(static_cast<double>(k) * step);
  return values;
}

std::string formatTick(double value, double step) {
  int decimals = 0;
  while (decimals < 6) {
    const double scaled = step * std::pow(10.0, decimals);
    if (std::abs(scaled - std::round(scaled)) < 1e-9 * std::max(1.0, scaled)) break;
    ++decimals;
  }
  if (std::abs(value) < step * 1e-9) value = 0.0;  // never "-0"
  return fmt::format("{:.{}f}", value, decimals);
}

std::string formatReading(double value) {
  if (!std::isfinite(value)) return "-";
  const double magnitude = std::abs(value);
  const int decimals = magnitude >= 100.0 ? 1 : magnitude >= 10.0 ? 2 : magnitude >= 1.0 ? 3 : 4;
  return fmt::format("{:.{}f}", value, decimals);
}

}  // namespace penumbra::viz
