#include "geometry/face_triangulation.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace penumbra {

double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

TriangleMesh triangulate(const ConvexPolygon& polygon, double spacing, int maxSubdivisions) {
  TriangleMesh mesh;
  const std::vector<Vec3>& v = polygon.vertices();
  double longest = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i)
    for (std::size_t j = i + 1; j < v.size(); ++j)
      longest = std::max(longest, (v[j] - v[i]).norm());
  const int n = std::clamp(static_cast<int>(std::ceil(longest / spacing)), 1, maxSubdivisions);
  std::map<std::array<double, 3>, int> shared;
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    // Fan triangle (v0, vk, vk+1) in barycentric steps of 1/n: row i runs from a to b.
    const Vec3 &a = v[0], &b = v[k], &c = v[k + 1];
    std::vector<int> local;                 // row-major (i, j) → mesh vertex
    const auto index = [&](int i, int j) {  // i along a→b, j along a→c, i + j <= n
      return local[i * (n + 1) - i * (i - 1) / 2 + j];
    };
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n - i; ++j) {
        const Vec3 p = a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n);
        // The points of an edge two fan triangles share come out bit for bit the same: one
        // vertex, so that both triangles share its contour crossings too.
        const auto [it, inserted] =
            shared.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(mesh.vertices.size()));
        if (inserted) mesh.vertices.push_back(p);
        local.push_back(it->second);
      }
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n - i; ++j) {
        mesh.triangles.push_back({index(i, j), index(i + 1, j), index(i, j + 1)});
        if (j + 1 <= n - i - 1)
          mesh.triangles.push_back({index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
      }
  }
  return mesh;
}

}  // namespace penumbra
