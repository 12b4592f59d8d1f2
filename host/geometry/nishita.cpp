#include "geometry/nishita.hpp"

namespace penumbra {

Side nishitaH(const Plane& face, std::span<const Vec3> points, double tolerance) {
  // Paper eq. 2 with closed half-spaces widened by the tolerance. Positive is tested first so
  // that a set lying in the plane (both tests pass) is Positive, as the header promises.
  bool allPositive = true;
  bool allNegative = true;
  for (const Vec3& p : points) {
    const double f = nishitaF(face, p);
    allPositive = allPositive && f >= -tolerance;
    allNegative = allNegative && f <= tolerance;
  }
  if (allPositive) return Side::Positive;
  if (allNegative) return Side::Negative;
  return Side::Straddles;
}

Side nishitaH(const Plane& face, const ConvexPolyhedron& v, double tolerance) {
  return nishitaH(face, std::span<const Vec3>(v.vertices()), tolerance);
}

Side nishitaH(const Plane& face, const ConvexPolygon& v, double tolerance) {
  return nishitaH(face, std::span<const Vec3>(v.vertices()), tolerance);
}

}  // namespace penumbra
