#pragma once
// The Unified Glare Rating of one eye along one line of sight (CIE 117-1995):
//   UGR = 8 log₁₀(0.25/L_b · Σ L²ω/p²)
// over the glare sources within the position index's range (position_index.hpp), L their
// luminance towards the eye (cd/m²), ω the solid angle of their visible part (sr), p the Guth
// index, and L_b the background luminance (cd/m²): the indirect illuminance at the eye on the
// plane facing the line of sight, over π.
//
// With L_b = 0 (direct light only, or a black room) the formula has no value: CIE 117 defines
// UGR for a lit background, so the rating is reported undefined, never infinite. So is a view
// with no glare source in range (the logarithm of 0): nothing there glares.
#include <optional>
#include <string>
#include <vector>

#include "glare/seen_sources.hpp"

namespace penumbra {

struct GlareTerm {
  std::string name;
  double luminance = 0.0;      // cd/m²
  double solidAngle = 0.0;     // sr
  double farFieldAngle = 0.0;  // sr, A_p/d², for comparison
  double positionIndex = 1.0;  // Guth p
  double value() const {
    return luminance * luminance * solidAngle / (positionIndex * positionIndex);
  }
};

struct GlareRating {
  Vec3 look = Vec3::UnitX();         // unit
  double backgroundLuminance = 0.0;  // cd/m²
  std::vector<GlareTerm> terms;      // in range, largest L²ω/p² first
  int outsideRange = 0;  // seen, but behind, below or beside the line of sight beyond Guth's range
  int withoutArea = 0;   // luminaire instances without a flat luminous area (EyeView)
  double sum() const;    // Σ L²ω/p², (cd/m²)²·sr
  std::optional<double> ugr;
};

// 8 log₁₀(0.25/L_b · Σ); nothing when L_b ≤ 0 or Σ ≤ 0 (see above).
std::optional<double> unifiedGlareRating(double sum, double backgroundLuminance);

// The rating of `view` along `look` (unit, with a horizontal component), with background
// luminance `backgroundLuminance` (cd/m²).
GlareRating rateView(const EyeView& view, const Vec3& look, double backgroundLuminance);

// The EN 12464-1 limits UGR_L (16, 19, 22, 25, 28): the strictest that `ugr` meets (ugr ≤ UGR_L),
// nothing above 28.
std::optional<int> strictestLimitMet(double ugr);

}  // namespace penumbra
