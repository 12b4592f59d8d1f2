#pragma once
// Closed forms for the illuminance from a region of the sphere whose luminance is a polynomial in
// the cosine to an axis (Arvo 1995, "Applications of irradiance tensors to the simulation of
// non-Lambertian phenomena": axial and double-axis moments, each a sum over the region's boundary,
// O(order) per edge by recurrence).
//
// For a region V of directions ω seen from a point with unit normal n, an axis w and g = w·ω:
//   M_k = ∫_V g^k (n·ω) dω,  k = 0..order.
// The surface divergence theorem on the sphere gives, with each boundary arc a → b of angle Θ,
// m = unit(b × a) (pointing into V) and F_k = ∫_0^Θ (w·u(θ))^k dθ along the arc:
//   (k + 2) M_k = k (w·n) τ_{k−1} + Σ (n·m) F_k
//   (k + 1) τ_k = (k − 1) τ_{k−2} + Σ (w·m) F_{k−1},   τ_0 = the solid angle of V
// where τ_k = ∫_V g^k dω. F_k follows the recurrence of ∫ cos^k: with x = w·a, y = w·t (t the
// arc's unit tangent at a), f(θ) = x cos θ + y sin θ,
//   k F_k = (k − 1)(x² + y²) F_{k−2} − [f^{k−1} f′]_0^Θ,   F_0 = Θ.
// M_0 is Lambert's formula: a Lambertian region of luminance L gives E = L · M_0.
#include <span>
#include <vector>

#include "reference/visible_boundary.hpp"

namespace penumbra {

// M_0..M_order over the region bounded by `arcs` (visible_boundary.hpp's orientation); w and n
// unit. Every direction of the region must have w·ω > −1 (the solid angle is summed from w).
std::vector<double> cosineMoments(std::span<const VisibleArc> arcs, const Vec3& w, const Vec3& n,
                                  int order);

}  // namespace penumbra
