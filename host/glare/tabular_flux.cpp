#include "glare/tabular_flux.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "photometry/photometric_frame.hpp"

namespace penumbra {
namespace {

constexpr int kZones = 18;            // 10° each, γ from 0 to 180°
constexpr int kAzimuthSamples = 720;  // every 0.5°, at the middle of each step
constexpr double kConeCosines[4] = {0.75, 0.5, 0.25, 0.0};

struct KRow {
  double k;
  GeometricMultipliers multipliers;
};

// CIE 190:2010, table 4: F_GL,1..4 by room index.
constexpr std::array<KRow, 13> kMultipliers = {{
    {1.00, {{0.690, 0.109, 0.085, -0.016}}},
    {1.20, {{0.578, 0.200, 0.127, -0.018}}},
    {1.33, {{0.528, 0.218, 0.170, -0.017}}},
    {1.50, {{0.485, 0.215, 0.222, -0.012}}},
    {1.60, {{0.466, 0.207, 0.249, -0.006}}},
    {1.71, {{0.448, 0.198, 0.272, 0.005}}},
    {2.00, {{0.338, 0.257, 0.351, -0.018}}},
    {2.40, {{0.296, 0.203, 0.449, -0.006}}},
    {2.67, {{0.280, 0.165, 0.499, 0.006}}},
    {3.00, {{0.264, 0.125, 0.541, 0.027}}},
    {3.43, {{0.248, 0.058, 0.628, 0.032}}},
    {4.00, {{0.239, -0.012, 0.690, 0.058}}},
    {4.80, {{0.232, -0.084, 0.740, 0.098}}},
}};

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

// The C-average of the intensity at γ (cd), by the midpoint rule over 0.5° steps of C: exact for
// a table interpolated linearly between planes at multiples of 0.5°.
double averageOverC(const photometry::LightDistribution& distribution, double gammaDeg) {
  double sum = 0.0;
  for (int i = 0; i < kAzimuthSamples; ++i) {
    const double c = (i + 0.5) * 360.0 / kAzimuthSamples;
    sum += distribution.intensity(
        photometry::directionOf(photometry::PhotometricType::C, {c, gammaDeg}));
  }
  return sum / kAzimuthSamples;
}

}  // namespace

ZonalCones zonalCones(const photometry::LightDistribution& distribution) {
  ZonalCones cones;
  for (int zone = 0; zone < kZones; ++zone) {
    const double top = 10.0 * zone, bottom = top + 10.0;
    const double cosTop = std::cos(radians(top)), cosBottom = std::cos(radians(bottom));
    const double flux =
        averageOverC(distribution, top + 5.0) * 2.0 * std::numbers::pi * (cosTop - cosBottom);
    if (zone >= kZones / 2) {
      cones.up += flux;
      continue;
    }
    cones.down += flux;
    for (int i = 0; i < 4; ++i) {
      const double edge = kConeCosines[i];
      if (cosBottom >= edge) {
        cones.cone[i] += flux;
      } else if (cosTop > edge) {
        cones.cone[i] += flux * (cosTop - edge) / (cosTop - cosBottom);
      }
    }
  }
  return cones;
}

std::optional<GeometricMultipliers> geometricMultipliers(double k) {
  for (const KRow& row : kMultipliers) {
    if (std::abs(row.k - k) <= 0.005) return row.multipliers;
  }
  return std::nullopt;
}

FluxFractions fluxFractions(const ZonalCones& cones, const GeometricMultipliers& multipliers) {
  const double total = cones.down + cones.up;
  FluxFractions fractions;
  if (!(total > 0.0)) return fractions;
  double toFloor = 0.0;
  for (int i = 0; i < 4; ++i) toFloor += multipliers.f[i] * cones.cone[i];
  fractions.toFloor = toFloor / total;
  fractions.toWalls = cones.down / total - fractions.toFloor;
  fractions.toCeiling = cones.up / total;
  return fractions;
}

}  // namespace penumbra
