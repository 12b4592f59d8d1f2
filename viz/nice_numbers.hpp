#pragma once
// Round numbers for legends, axes and isolux levels: the 1-2-5 series (…, 0.5, 1, 2, 5, 10, …),
// the steps people read without effort.
#include <string>
#include <vector>

namespace penumbra::viz {

// The smallest value of the 1-2-5 series >= x, and the largest <= x (x > 0).
double oneTwoFiveAtLeast(double x);
double oneTwoFiveAtMost(double x);

// The values of the 1-2-5 series strictly between lo and hi (lo >= 0).
std::vector<double> oneTwoFiveBetween(double lo, double hi);

// The multiples of `step` in [lo, hi], computed as k·step so that they print cleanly.
std::vector<double> multiplesOf(double step, double lo, double hi);

// A multiple of `step` written with just the digits it needs ("0.5", "2", "1500").
std::string formatTick(double value, double step);

// An illuminance (or any reading) for a label: four significant digits, at most one decimal
// above 100 ("2349.4", "359.5", "12.35", "0.05") and no exponent.
std::string formatReading(double value);

}  // namespace penumbra::viz
