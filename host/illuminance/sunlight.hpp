#pragma once
// Direct sunlight (docs/method.md, "The sun"), exact in double on the host. The sun is a disk of
// kSunDiameterDegrees: a regular kSunPolygonSides-gon inscribed in it, placed per receiving point
// P at a distance D along the sun's direction (beyond every solid), emitting towards P with the
// uniform luminance L that gives an unobstructed plane facing the sun exactly E_dn:
//   L = E_dn / ∫_disk (s·ω) dω,   s the sun's direction,
// the integral the polygon's exact projected solid angle. Since only the directions from P
// matter, the polygon at any such D is the sun's disk seen from P. E at P is Lambert's contour
// integral over the part of the polygon that P sees past the solids (reference/visible_boundary
// .hpp), so the umbra and the penumbra of every edge (a window's jambs, sill and head, the
// reveals of a thick wall) are exact to rounding.
//
// Through a room's openings: a point inside the room (its interior box) sees the sun through one
// opening or none; the polygon is cut by the planes through P and the edges of each opening's
// outer rectangle, and each part counts times that opening's transmittance τ (light through
// glazing counted once, as the sky's). A point in an opening's tunnel through the wall (on its
// reveals) sees the sun past the solids, times that opening's τ (the glazing is at the outer
// rectangle); a point elsewhere outside the room past the solids, with no glazing. A sun below
// the horizon (Sun::aboveHorizon) gives 0.
#include <span>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

inline constexpr int kSunPolygonSides = 32;

// The sun's polygon seen from `point`: kSunPolygonSides vertices on the circle of angular radius
// kSunDiameterDegrees / 2 about `direction` (unit) at `distance` (m), its normal towards `point`.
ConvexPolygon sunPolygon(const Vec3& point, const Vec3& direction, double distance);

// cd/m²: the luminance of the polygon that gives `directNormalIlluminance` (lx) on an
// unobstructed plane facing the sun.
double sunLuminance(double directNormalIlluminance);

// E_sun in lx at every point; zeros without a sun or with the sun below the horizon. With
// `beam`, also per point whether it lies in the sun's beam before the solids are counted: some
// of the disk above its horizon is seen through an opening (a point inside the room) or at all
// (a point elsewhere); 0 where the sun cannot reach it whatever stands in the room.
std::vector<double> sunlight(const Scene& scene, std::span<const SamplePoint> points,
                             std::vector<char>* beam = nullptr);

}  // namespace penumbra
