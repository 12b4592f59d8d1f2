#pragma once
// The area model in double on the host (docs/method.md, "The area model"): E at a point from one
// placed luminaire's luminous opening, emitting the fitted luminance L(cos φ) = Σ c_k cos^k φ
// (φ from the opening's normal N), integrated exactly over the part of the opening the point
// sees:
//   E = s · Σ_k c_k ∫_V (w·ω)^k (n·ω) dω,   w = −N,
// s the luminaire's intensity scale, V the visible part (visible_boundary.hpp) and the integrals
// the closed forms of cosine_moments.hpp.
#include <span>

#include "geometry/convex_polygon.hpp"
#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// The opening of `instance` in scene coordinates (its normal the emission direction N).
ConvexPolygon placedOpening(const LuminaireOpening& opening, const LuminaireInstance& instance);
// The same for an outline in the luminaire's local frame (Luminaire::luminousOutline).
ConvexPolygon placedOutline(std::span<const Vec3> outline, const LuminaireInstance& instance);

// E in lx at `point` from `instance` of `luminaire` (its model Area, not subdivided); `tolerance`
// the scene's length tolerance (m).
double openingIlluminance(const Luminaire& luminaire, const LuminaireInstance& instance,
                          const SamplePoint& point, const Scene& scene, double tolerance);

}  // namespace penumbra
