#pragma once
// The flux fractions of the CIE 190 tabular method: how a luminaire's flux first divides between
// the reference plane at eye height ("floor"), the walls and the luminaires' plane ("ceiling") of
// a standard room with room index k = XY / (H(X + Y)).
//
// The flux of the table in 18 zones of 10° of γ, each the C-average of the intensity at the
// zone's middle times the zone's solid angle 2π(cos γ1 − cos γ2); from the downward zones the
// cumulative fluxes Φ_1..Φ_4 of the cones cos γ ≥ 0.75, 0.5, 0.25, 0 (41.4°, 60°, 75.5°, 90°; a
// zone the cone's edge cuts counts with the share of its solid angle inside). Then, with CIE 190's
// geometric multipliers F_GL,1..4 for the room's k (its table 4):
//   F_DF = Σ F_GL,i Φ_i / Φ    direct to the floor
//   F_DW = Φ_down / Φ − F_DF   direct to the walls
//   F_DC = Φ_up / Φ            to the ceiling
// Φ the sum of the 18 zones. The multipliers are the standard's fit of the direct flux a regular
// array of luminaires sends onto the floor of a room of index k, not a closed form: they are data.
#include <optional>

#include "photometry/light_distribution.hpp"

namespace penumbra {

struct FluxFractions {
  double toFloor = 0.0;    // F_DF
  double toWalls = 0.0;    // F_DW
  double toCeiling = 0.0;  // F_DC
};

// The cumulative downward fluxes of the four cones and the downward and upward flux, lm.
struct ZonalCones {
  double cone[4] = {0.0, 0.0, 0.0, 0.0};  // cos γ ≥ 0.75, 0.5, 0.25, 0
  double down = 0.0, up = 0.0;
};

ZonalCones zonalCones(const photometry::LightDistribution& distribution);

// CIE 190's F_GL,1..4 for room index `k`: the standard's rooms have the 13 indices 1.00, 1.20,
// 1.33, 1.50, 1.60, 1.71, 2.00, 2.40, 2.67, 3.00, 3.43, 4.00, 4.80; nothing for another k (more
// than 0.005 from all of them).
struct GeometricMultipliers {
  double f[4] = {0.0, 0.0, 0.0, 0.0};
};
std::optional<GeometricMultipliers> geometricMultipliers(double k);

// The fractions for a room of index `k` (one of the standard's, see above).
FluxFractions fluxFractions(const ZonalCones& cones, const GeometricMultipliers& multipliers);

}  // namespace penumbra
