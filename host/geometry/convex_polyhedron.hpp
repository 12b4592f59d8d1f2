#pragma once
#include <optional>
#include <vector>

#include "geometry/convex_polygon.hpp"

namespace penumbra {

// A bounded convex polyhedron: vertices, faces (vertex loops counter-clockwise seen from
// outside, with outward planes) and edges with their two faces. Built only through the
// factories, which guarantee that representation (coplanar hull facets merged, no duplicate
// vertices).
class ConvexPolyhedron {
 public:
  struct Face {
    std::vector<int> vertices;  // counter-clockwise about plane.normal (outward)
    Plane plane;
  };
  struct Edge {
    int from = -1, to = -1;
    int left = -1;   // the face whose loop runs from -> to
    int right = -1;  // the face whose loop runs to -> from
  };

  ConvexPolyhedron() = default;  // empty

  static ConvexPolyhedron box(const Vec3& min, const Vec3& max);
  // The prism over a convex base polygon, extruded by `extrusion` (any side of the base).
  static ConvexPolyhedron prism(const ConvexPolygon& base, const Vec3& extrusion, double tolerance);
  // Convex hull of points; empty when the points span no volume (all within tolerance of a plane).
  static ConvexPolyhedron hull(const std::vector<Vec3>& points, double tolerance);

  bool empty() const { return faces_.empty(); }
  const std::vector<Vec3>& vertices() const { return vertices_; }
  const std::vector<Face>& faces() const { return faces_; }
  const std::vector<Edge>& edges() const { return edges_; }

  ConvexPolygon facePolygon(int face) const;
  double volume() const;
  Vec3 centroid() const;  // volume centroid
  double surfaceArea() const;
  // The smallest width measured across a face (the distance from a face's plane to the farthest
  // vertex behind it, least over the faces): a slab's thickness, a box's shortest side.
  double thickness() const;

  // The part inside the half-space signedDistance <= 0 of `boundary`. Empty when nothing with
  // volume (thicker than tolerance) remains.
  ConvexPolyhedron clipped(const Plane& boundary, double tolerance) const;

  // True when p is inside by more than tolerance from every face.
  bool containsStrictly(const Vec3& p, double tolerance) const;
  // The face whose plane passes within tolerance of p, with p inside all other planes
  // (p lies on that face); -1 when none. Ties go to the face whose normal best matches `normal`.
  int faceContaining(const Vec3& p, const Vec3& normal, double tolerance) const;

  // Nishita's contour line: the loop of vertices on edges between a face that has `viewpoint`
  // in its positive space and one that does not, counter-clockwise as seen from viewpoint.
  // Empty when the viewpoint is inside or on the boundary.
  std::vector<Vec3> silhouette(const Vec3& viewpoint) const;

 private:
  // Builds edges from faces; used by the factories.
  static ConvexPolyhedron fromFaces(std::vector<Vec3> vertices, std::vector<Face> faces);

  std::vector<Vec3> vertices_;
  std::vector<Face> faces_;
  std::vector<Edge> edges_;
};

}  // namespace penumbra
