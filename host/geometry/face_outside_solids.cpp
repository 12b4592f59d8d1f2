#include "geometry/face_outside_solids.hpp"

#include "geometry/bounding_box.hpp"

namespace penumbra {
namespace {

BoundingBox boxOf(const std::vector<Vec3>& points) {
  BoundingBox box;
  for (const Vec3& p : points) box.add(p);
  return box;
}

// Pieces no wider than this many tolerances are left out (hasArea).
constexpr double kStripWidths = 4.0;

bool hasArea(const ConvexPolygon& polygon, double tolerance) {
  if (polygon.empty()) return false;
  double longest = 0.0;
  const auto& v = polygon.vertices();
  for (std::size_t i = 0; i < v.size(); ++i)
    longest = std::max(longest, (v[(i + 1) % v.size()] - v[i]).norm());
  // area / longest edge bounds the width. The pieces are cut along each solid's planes grown by
  // the tolerance, so where two solids meet (a wall's slabs beside a window) the cuts along
  // their common plane lie twice the tolerance apart, and the strip between them is dropped: its
  // area is nothing, and as an element its two long edges coincide in the kernel's float.
  return polygon.area() > kStripWidths * tolerance * longest;
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
