#include "geometry/face_outside_solids.hpp"

#include "geometry/bounding_box.hpp"

namespace penumbra {
namespace {

BoundingBox boxOf(const std::vector<Vec3>& points) {
  BoundingBox box;
  for (const Vec3& p : points) box.add(p);
  return box;
}

bool hasArea(const ConvexPolygon& polygon, double tolerance) {
  if (polygon.empty()) return false;
  double longest = 0.0;
  const auto& v = polygon.vertices();
  for (std::size_t i = 0; i < v.size(); ++i)
    longest = std::max(longest, (v[(i + 1) % v.size()] - v[i]).norm());
  // Thinner than the tolerance everywhere: area / longest edge bounds the width.
  return polygon.area() > tolerance * longest;
}

}  // namespace

std::vector<ConvexPolygon> faceOutsideSolids(const ConvexPolygon& face,
                                             const std::vector<const ConvexPolyhedron*>& others,
                                             double tolerance) {
  std::vector<ConvexPolygon> pieces{face};
  const BoundingBox faceBox = boxOf(face.vertices()).grown(tolerance);
  for (const ConvexPolyhedron* solid : others) {
    if (solid->empty() || !boxOf(solid->vertices()).overlaps(faceBox)) continue;
    std::vector<ConvexPolygon> next;
    for (const ConvexPolygon& piece : pieces) {
      ConvexPolygon inside = piece;
      for (const ConvexPolyhedron::Face& f : solid->faces()) {
        // A point within tolerance of the plane counts as inside: a face resting on the solid
        // (the floor under a wall) is covered by it.
        ConvexPolygon outside =
            inside.clipped(Plane{-f.plane.normal, -(f.plane.offset + tolerance)}, 0.0);
        if (hasArea(outside, tolerance)) next.push_back(std::move(outside));
        inside = inside.clipped(Plane{f.plane.normal, f.plane.offset + tolerance}, 0.0);
        if (!hasArea(inside, tolerance)) break;
      }
    }
    pieces = std::move(next);
  }
  return pieces;
}

}  // namespace penumbra
