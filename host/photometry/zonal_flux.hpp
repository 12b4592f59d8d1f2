#pragma once
// The luminous flux of a distribution by the zonal method on the table's own nodes, and its
// comparison with the flux the file states (lamp lumens x LOR).
//
// Each node stands for the zone between the midpoints to its neighbours (clipped to the measured
// range): in its plane a zone of solid angle (cos γ1 - cos γ2) per radian of plane (type C; for
// types A and B, whose in-plane angle is a latitude, sin φ2 - sin φ1), and across planes the
// plane's share of the circle, half the gap to each neighbour. Type C planes cover 360°, so a
// zone's constant is 2π (cos γ1 - cos γ2) times the C-average of the intensity. For I = I0 cos γ
// tabulated every Δ from 0 to 90° the sum is π I0 (2 - 1/cos(Δ/2)), 0.095 % below π I0 at
// Δ = 5° (docs/photometry.md).
#include <optional>

#include "photometry/light_distribution.hpp"
#include "photometry/photometric_data.hpp"

namespace penumbra::photometry {

// lm from the table (cd x sr).
double zonalFlux(const LightDistribution& distribution);

struct FluxComparison {
  double zonalLm = 0;
  std::optional<double> fileLm;              // lamp lumens x LOR, when the file gives both
  std::optional<double> relativeDifference;  // (zonal - file) / file
};

FluxComparison compareFlux(const PhotometricData& data, const LightDistribution& distribution);

}  // namespace penumbra::photometry
