#include "scene/cie_general_sky.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace penumbra {
namespace {

// φ(Z) with cos Z given: 1 at and below the horizon (exp(b / cos Z) → 0 as cos Z → 0+).
double cieGradation(const CieSkyParameters& p, double cosZenith) {
  if (!(cosZenith > 0.0)) return 1.0;
  return 1.0 + p.a * std::exp(p.b / cosZenith);
}

// f(χ) with χ the angle (rad).
double cieIndicatrix(const CieSkyParameters& p, double chi) {
  const double c = std::cos(chi);
  return 1.0 + p.c * (std::exp(p.d * chi) - std::exp(p.d * std::numbers::pi / 2.0)) + p.e * c * c;
}

double angleBetween(const Vec3& u, const Vec3& v) {
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

}  // namespace

const CieSkyParameters& cieSkyParameters(int type) {
  if (type < 1 || type > kCieSkyTypes)
    throw std::out_of_range("CIE sky type " + std::to_string(type) + ": the types are 1 to 15");
  return kCieSkyTable[static_cast<std::size_t>(type - 1)];
}

bool dependsOnSun(const CieSkyParameters& p) {
  return p.c != 0.0 || p.e != 0.0;
}

double cieRelativeLuminance(const CieSkyParameters& p, const Vec3& omega, const Vec3& sun) {
  const double sunZenith = std::acos(std::clamp(sun.z(), -1.0, 1.0));
  const double chi = angleBetween(omega, sun);
  return cieIndicatrix(p, chi) * cieGradation(p, omega.z()) /
         (cieIndicatrix(p, sunZenith) * cieGradation(p, 1.0));
}

}  // namespace penumbra
