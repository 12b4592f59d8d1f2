#pragma once
// The CIE standard general sky (ISO 15469:2004 / CIE S 011/E:2003): 15 relative luminance
// distributions, each a gradation φ(Z) and an indicatrix f(χ):
//   L(ω) / L_z = f(χ) φ(Z) / (f(Z_s) φ(0)),
//   φ(Z) = 1 + a exp(b / cos Z)   (φ = 1 at the horizon, cos Z = 0, since b < 0),
//   f(χ) = 1 + c (exp(d χ) − exp(d π/2)) + e cos² χ,
// Z the zenith angle of the sky element, Z_s the sun's, χ the angle between the element and the
// sun. Types 1, 3 and 5 (c = e = 0) do not depend on the sun.
#include <array>

#include "geometry/vec.hpp"

namespace penumbra {

struct CieSkyParameters {
  double a, b;     // gradation
  double c, d, e;  // indicatrix
};

inline constexpr int kCieSkyTypes = 15;

// Table 1 of ISO 15469:2004 / CIE S 011/E:2003 (the same values: Darula and Kittler, "CIE general
// sky standard defining luminance distributions", eSim 2002): types 1 to 15, in order.
inline constexpr std::array<CieSkyParameters, kCieSkyTypes> kCieSkyTable = {{
    {4.0, -0.70, 0.0, -1.0, 0.00},    // 1 CIE standard overcast sky, steep gradation
    {4.0, -0.70, 2.0, -1.5, 0.15},    // 2 overcast, steep gradation, slight brightening to the sun
    {1.1, -0.80, 0.0, -1.0, 0.00},    // 3 overcast, moderate gradation, azimuthal uniformity
    {1.1, -0.80, 2.0, -1.5, 0.15},    // 4 overcast, moderate gradation, slight brightening
    {0.0, -1.00, 0.0, -1.0, 0.00},    // 5 sky of uniform luminance
    {0.0, -1.00, 2.0, -1.5, 0.15},    // 6 partly cloudy, no gradation, slight brightening
    {0.0, -1.00, 5.0, -2.5, 0.30},    // 7 partly cloudy, no gradation, brighter circumsolar region
    {0.0, -1.00, 10.0, -3.0, 0.45},   // 8 partly cloudy, no gradation, distinct solar corona
    {-1.0, -0.55, 2.0, -1.5, 0.15},   // 9 partly cloudy, the sun obscured
    {-1.0, -0.55, 5.0, -2.5, 0.30},   // 10 partly cloudy, brighter circumsolar region
    {-1.0, -0.55, 10.0, -3.0, 0.45},  // 11 white-blue sky, distinct solar corona
    {-1.0, -0.32, 10.0, -3.0, 0.45},  // 12 CIE standard clear sky, low turbidity
    {-1.0, -0.32, 16.0, -3.0, 0.30},  // 13 CIE standard clear sky, polluted atmosphere
    {-1.0, -0.15, 16.0, -3.0, 0.30},  // 14 cloudless turbid sky, broad solar corona
    {-1.0, -0.15, 24.0, -2.8, 0.15},  // 15 white-blue turbid sky, broad solar corona
}};

// The parameters of type 1..15.
const CieSkyParameters& cieSkyParameters(int type);

// Whether the distribution depends on the sun's position (c or e non-zero).
bool dependsOnSun(const CieSkyParameters& p);

// L(ω)/L_z for the unit direction ω (z up, ω_z >= 0) with the sun towards the unit `sun`.
double cieRelativeLuminance(const CieSkyParameters& p, const Vec3& omega, const Vec3& sun);

}  // namespace penumbra
