#include "shadow/face_class.hpp"

#include "geometry/nishita.hpp"

namespace penumbra {

FaceClass classifyFace(const ConvexPolygon& face, const ConvexPolygon& source, double tolerance) {
  const Side sourceSide = nishitaH(face.plane(), source, tolerance);
  const Side faceSide = nishitaH(source.plane(), face, tolerance);
  if (sourceSide == Side::Negative || faceSide == Side::Negative) return FaceClass::C;
  return sourceSide == Side::Positive ? FaceClass::A : FaceClass::B;
}

FaceClass classifyFace(const ConvexPolygon& face, const ConvexPolyhedron& source,
                       double tolerance) {
  switch (nishitaH(face.plane(), source, tolerance)) {
    case Side::Positive:
      return FaceClass::A;
    case Side::Negative:
      return FaceClass::C;
    case Side::Straddles:
      break;
  }
  return FaceClass::B;
}

FaceClass classifyPoint(const Vec3& point, const Vec3& normal, std::span<const Vec3> sourceVertices,
                        const Plane& emission) {
  // The kernel gives 0 to a point that is not strictly in front of the emitting plane, and keeps
  // the part of the source with normal·(q − point) >= 0; these are the same comparisons.
  if (emission.signedDistance(point) <= 0.0) return FaceClass::C;
  bool allAbove = true, anyAbove = false;
  for (const Vec3& q : sourceVertices) {
    const double h = normal.dot(q - point);
    allAbove = allAbove && h > 0.0;
    anyAbove = anyAbove || h > 0.0;
  }
  if (!anyAbove) return FaceClass::C;
  return allAbove ? FaceClass::A : FaceClass::B;
}

}  // namespace penumbra
