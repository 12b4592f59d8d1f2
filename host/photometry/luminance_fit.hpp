#pragma once
// The area model's luminance (docs/method.md, "The area model"): a flat luminous opening of area
// A, facing the local −z (the nadir), emits L(ω) = I(ω) / (A cos φ) uniformly over its area,
// φ the angle between the emitted direction and the nadir (Radiance ies2rad's model). The fit is
// a polynomial in cos φ,
//   L(cos φ) = Σ_{k=0..order} c_k cos^k φ,
// by least squares on the intensity A cos φ · L at every node of the table in front of the
// opening (cos φ > 0), so that each C plane weighs alike and the fit is the rotational mean of
// the distribution about the nadir. Its error is the largest |A cos φ L − I| over all the table's
// nodes (those behind the opening count with the fit's 0 there), relative to the peak candela:
// what an asymmetric or narrow distribution loses to the fit.
//
// Two kinds of fit are tried, the first that holds is kept: the least-squares polynomial of the
// lowest order 0..kLuminanceFitMaxOrder within the tolerance and kLuminanceConditioningLimit;
// else a sum of powers with nonnegative coefficients, c_k >= 0 for k up to kLuminanceFitMaxPower
// (nonnegative least squares, Lawson–Hanson), of the lowest highest power within the tolerance. A
// narrow beam is such a sum (a beam of half-value angle α is near cos^n φ with n = ln 2 / −ln cos
// α: 40 at 10.5°), and a sum of nonnegative terms never cancels: its conditioning is 1. The
// kernel integrates each power with recurrences chosen per arc to stay accurate where cos^k φ is
// small over the arc (kernels/luminance_moments.cl).
#include <vector>

#include "photometry/light_distribution.hpp"

namespace penumbra::photometry {

// The error a fit may have (relative to the peak) for the area model to integrate it exactly;
// beyond it the opening is split into parts, each a point source (scene/luminaire.hpp).
constexpr double kLuminanceFitTolerance = 0.01;
// The highest order of the least-squares polynomial.
constexpr int kLuminanceFitMaxOrder = 12;
// The highest power of the nonnegative fit (the kernel stores c_0..c_48: PN_MAX_LUMINANCE_TERMS).
// A beam narrower than cos^48 (half value at 9.7°) is split into parts.
constexpr int kLuminanceFitMaxPower = 48;
// The largest conditioning (LuminanceFit::conditioning) the area model integrates: the kernel sums
// Σ c_k M_k in float, each M_k good to about (order + 4) roundings of itself, so the sum is good to
// about conditioning · (order + 4) · 2⁻²⁴ of the largest luminance: at most 3.8e-6 at order 12.
// A polynomial beyond it (a narrow beam's, whose coefficients alternate in sign and reach 10⁵
// times the luminance) gives way to the nonnegative fit, whose conditioning is 1.
constexpr double kLuminanceConditioningLimit = 4.0;

struct LuminanceFit {
  std::vector<double> coefficients;  // c_0..c_order, cd/m² (the file's table, unscaled); the
                                     // nonnegative fit's are mostly 0
  double openingAreaM2 = 0.0;
  double peakRelativeError = 0.0;  // at the table's nodes, relative to the peak candela

  int order() const { return static_cast<int>(coefficients.size()) - 1; }
  // Σ |c_k| / max |L(cos φ)| over cos φ in [0, 1]: what cancellation in the monomial sum can cost
  // relative to the luminance (1 for a constant).
  double conditioning() const;
  double luminance(double cosPhi) const;  // cd/m²
  double intensity(double cosPhi) const;  // cd: A cos φ L, 0 for cos φ <= 0
};

// The least-squares polynomial of the lowest order (0..maxOrder) whose error is within
// `tolerance` and whose conditioning is within kLuminanceConditioningLimit; else the nonnegative
// sum of powers (maxOrder + 1..kLuminanceFitMaxPower) of the lowest highest power within
// `tolerance`; else the polynomial with the least error. `areaM2` > 0.
LuminanceFit fitLuminance(const LightDistribution& distribution, double areaM2,
                          double tolerance = kLuminanceFitTolerance,
                          int maxOrder = kLuminanceFitMaxOrder);

}  // namespace penumbra::photometry
