#pragma once
// Exact geometric predicates on double inputs (Shewchuk's floating-point filter with an exact
// expansion-arithmetic fallback). Used where a wrong sign breaks a combinatorial structure
// rather than moving a point: the convex hull's visibility test.
#include "geometry/vec.hpp"

namespace penumbra {

// Sign of det[b - a; c - a; p - a] = ((b - a) x (c - a)) . (p - a), computed exactly: +1 when p
// is on the side the right-hand normal of the triangle (a, b, c) points to, -1 on the other,
// 0 when the four points are exactly coplanar.
int orientationSign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& p);

}  // namespace penumbra
