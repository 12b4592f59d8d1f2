#include "photometry/field_checks.hpp"

#include <fmt/format.h>

#include <cmath>

#include "photometry/photometric_error.hpp"

namespace penumbra::photometry {

void checkAngles(const NumberedValues& angles, const std::filesystem::path& file,
                 const std::string& field, double minDeg, double maxDeg) {
  for (std::size_t i = 0; i < angles.values.size(); ++i) {
    const double a = angles.values[i];
    if (!(a >= minDeg && a <= maxDeg)) {
      throw PhotometricError(file, angles.lines[i], field,
                             fmt::format("angle {} of {} is {}°, outside {}° to {}°", i + 1,
                                         angles.values.size(), a, minDeg, maxDeg));
    }
    if (i > 0 && !(a > angles.values[i - 1])) {
      throw PhotometricError(
          file, angles.lines[i], field,
          fmt::format("not increasing: angle {} is {}° after {}°", i + 1, a, angles.values[i - 1]));
    }
  }
}

int wholeNumber(double value, int min, int max, const std::string& meaning,
                const std::filesystem::path& file, int line, const std::string& field) {
  if (value != std::floor(value) || value < min || value > max) {
    std::string text = fmt::format("{} is not a whole number from {} to {}", value, min, max);
    if (!meaning.empty()) text += " (" + meaning + ")";
    throw PhotometricError(file, line, field, text);
  }
  return static_cast<int>(value);
}

double candelaOf(double value, double factor, int line, const std::filesystem::path& file,
                 const std::string& field, const std::string& where) {
  if (!std::isfinite(value)) {
    throw PhotometricError(file, line, field, fmt::format("not a finite number at {}", where));
  }
  if (value < 0) {
    throw PhotometricError(file, line, field, fmt::format("negative value {} at {}", value, where));
  }
  const double cd = value * factor;
  if (!(cd <= kMaxCandela)) {
    throw PhotometricError(file, line, field,
                           fmt::format("{} x {} = {} cd at {}: above 10^12 cd, no luminaire's "
                                       "intensity",
                                       value, factor, cd, where));
  }
  return cd;
}

}  // namespace penumbra::photometry
