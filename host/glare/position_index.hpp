#pragma once
// The Guth position index p of a glare source (CIE 117-1995): how much less a source glares the
// further it lies from the line of sight. p grows from 1 on the line of sight; UGR divides each
// source's L²ω by p².
//
// p is the closed form of Luckiesh and Guth's data (the IES formula, whose values CIE 117
// tabulates against H/R and T/R):
//   ln p = (35.2 − 0.31889 τ − 1.22 e^(−2τ/9)) · 10⁻³ σ + (21 + 0.26667 τ − 0.002963 τ²) · 10⁻⁵ σ²
// with σ the angle in degrees between the line of sight and the direction to the source, and τ
// the angle in degrees between the vertical plane through the line of sight and the plane
// through the line of sight and the source. With R the source's distance along the line of sight,
// H its height above it and T its lateral offset, τ = atan(T/H) and σ = atan(√(H² + T²)/R).
//
// Validity, as CIE 117 applies it: the source in front of the eye (R > 0), at or above the line
// of sight (H ≥ 0; Guth's data are for sources above it), within the table's range
// H/R ≤ 1.9 and T/R ≤ 3.0. Sources outside it are left out of the sum and counted.
#include <optional>

#include "geometry/vec.hpp"

namespace penumbra {

// A line of sight and the directions of Guth's geometry: `forward` along it, `up` in the vertical
// plane through it, `right` across it; unit and orthogonal.
struct SightFrame {
  Vec3 forward, up, right;
  // The frame of `look` (non-zero, not vertical).
  static SightFrame along(const Vec3& look);
};

// A source's place relative to a line of sight (m): R along it, H above it, T across it (≥ 0).
struct SourcePosition {
  double along = 0.0, above = 0.0, across = 0.0;
};

// `toSource`: from the eye to the source's centre, m.
SourcePosition sourcePosition(const SightFrame& sight, const Vec3& toSource);

inline constexpr double kGuthMaxHeightRatio = 1.9;   // H/R, the end of CIE 117's table
inline constexpr double kGuthMaxLateralRatio = 3.0;  // T/R

// p for a source at `position`; nothing outside the validity range above.
std::optional<double> guthPositionIndex(const SourcePosition& position);

}  // namespace penumbra
