#pragma once
#include "geometry/vec.hpp"

namespace penumbra {

// The plane {x : normal·x = offset}, normal of unit length. As a half-space it is the closed
// set signedDistance(x) <= 0 ("inside", the convention of polyhedron faces with outward
// normals). Nishita's F_S(P) is signedDistance: positive-space = the side the normal points to.
struct Plane {
  Vec3 normal = Vec3::UnitZ();
  double offset = 0.0;

  static Plane through(const Vec3& point, const Vec3& normal) {
    const Vec3 n = normal.normalized();
    return Plane{n, n.dot(point)};
  }
  double signedDistance(const Vec3& x) const { return normal.dot(x) - offset; }
  Plane flipped() const { return Plane{-normal, -offset}; }
};

}  // namespace penumbra
