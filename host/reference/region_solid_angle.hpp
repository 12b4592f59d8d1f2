#pragma once
// The solid angle of a region of directions bounded by arcs (visible_boundary.hpp's orientation),
// in double: the fan of triangles (w, a, b) over the boundary's pieces a → b, each by Van
// Oosterom and Strackee's closed form (IEEE Trans. Biomed. Eng. 30, 1983),
//   tan(Ω/2) = w·(b × a) / (1 + w·a + a·b + w·b)   (unit vectors),
// signed so that the triangles outside the region cancel. Exact up to rounding for any region
// whose every direction ω has w·ω > −1 (a region in front of the eye with w towards it).
#include <span>

#include "reference/visible_boundary.hpp"

namespace penumbra {

// Ω in sr of the region bounded by `arcs`; w unit.
double regionSolidAngle(std::span<const VisibleArc> arcs, const Vec3& w);

// The signed solid angle of the triangle (w, a, b), all unit: positive when w·(b × a) > 0.
double triangleSolidAngle(const Vec3& w, const Vec3& a, const Vec3& b);

}  // namespace penumbra
