#pragma once

#include <numbers>

namespace penumbra {

// Degrees, as scene files, photometric files and reports give angles, to the radians of the
// trigonometric functions and back.
inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

}  // namespace penumbra
