#pragma once
// A convex polygon cut into small triangles: a fan from its first vertex, each fan triangle
// subdivided n × n (n from the longest edge and the wanted spacing, the same n for every fan
// triangle so that shared edges are cut at the same points and the mesh is conforming).
#include <array>
#include <vector>

#include "geometry/convex_polygon.hpp"

namespace penumbra {

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise as the polygon
};

// `spacing` (m, > 0): the longest side of a small triangle is at most about that.
TriangleMesh triangulate(const ConvexPolygon& polygon, double spacing, int maxSubdivisions = 64);

double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace penumbra
