#pragma once
#include <vector>

#include "geometry/plane.hpp"
#include "geometry/tolerance.hpp"

namespace penumbra {

// A planar convex polygon in 3-D. Its orientation is the vertex order: normal() is the
// right-hand (counter-clockwise) normal of that order.
class ConvexPolygon {
 public:
  ConvexPolygon() = default;
  explicit ConvexPolygon(std::vector<Vec3> vertices);

  const std::vector<Vec3>& vertices() const { return vertices_; }
  int size() const { return static_cast<int>(vertices_.size()); }
  bool empty() const { return vertices_.size() < 3; }

  Vec3 normal() const;    // unit right-hand normal of the vertex order (Newell's method)
  double area() const;    // >= 0
  Vec3 centroid() const;  // area centroid
  Plane plane() const;    // through the polygon, normal = normal()

  // Input checks, with an absolute length tolerance.
  bool isPlanar(double tolerance) const;
  bool isConvex(double tolerance) const;  // strictly convex turning, no collinear triples needed

  // The part inside the half-space signedDistance <= 0 of `boundary` (Sutherland-Hodgman).
  // Vertices within `tolerance` of the plane count as on it. May return an empty polygon.
  ConvexPolygon clipped(const Plane& boundary, double tolerance) const;
  ConvexPolygon reversed() const;

 private:
  std::vector<Vec3> vertices_;
};

}  // namespace penumbra
