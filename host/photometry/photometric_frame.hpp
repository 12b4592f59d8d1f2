#pragma once
// The luminaire's local frame and the angles of each photometric type (docs/photometry.md):
// z up, the nadir along -z, C0 along +x and C90 along +y.
//   type C: d = (sin γ cos C, sin γ sin C, -cos γ)        C = horizontal angle, γ = vertical
//   type B: d = (cos H sin V, sin H, -cos H cos V)        polar axis +y, V turns the plane about it
//   type A: d = (sin V, cos V sin H, -cos V cos H)        polar axis +x, H turns the plane about it
// Types A and B have their optical axis (H = V = 0) along -z, so that a floodlight aimed down
// shines like a downlight.
#include "geometry/vec.hpp"
#include "photometry/photometric_data.hpp"

namespace penumbra::photometry {

// Angles in degrees, named as the file names them.
struct TableAngles {
  double horizontalDeg = 0;  // C (type C) or H (types A and B)
  double verticalDeg = 0;    // γ (type C) or V (types A and B)
};

// The unit direction of `angles` in the local frame.
Vec3 directionOf(PhotometricType type, const TableAngles& angles);

// The angles of a direction (need not be unit, must not be zero): type C gives C in [0, 360) and
// γ in [0, 180]; type B H in [-90, 90] and V in (-180, 180]; type A H in (-180, 180] and V in
// [-90, 90].
TableAngles anglesOf(PhotometricType type, const Vec3& direction);

}  // namespace penumbra::photometry
