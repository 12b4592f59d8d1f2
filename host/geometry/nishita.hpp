#pragma once
// Nishita & Nakamae's two functions (paper eq. 1 and 2).
#include <span>

#include "geometry/convex_polyhedron.hpp"

namespace penumbra {

// F_S(P): signed distance of P from the plane of face S, positive in its positive space.
inline double nishitaF(const Plane& face, const Vec3& p) {
  return face.signedDistance(p);
}

enum class Side { Positive = 1, Negative = -1, Straddles = 0 };

// H(S, V): +1 when every vertex of V is in the closed positive space of S, -1 when every vertex
// is in the closed negative space, 0 when the plane of S cuts V. Points within tolerance of the
// plane count as on it; a set lying in the plane is Positive.
Side nishitaH(const Plane& face, std::span<const Vec3> points, double tolerance);
Side nishitaH(const Plane& face, const ConvexPolyhedron& v, double tolerance);
Side nishitaH(const Plane& face, const ConvexPolygon& v, double tolerance);

}  // namespace penumbra
