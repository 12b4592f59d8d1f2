#include "geometry/convex_polygon.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace penumbra {
namespace {

// Newell's vector: twice the area times the unit normal. Exact for planar polygons and the
// least-squares normal for slightly non-planar ones, and it never depends on which three
// vertices happen to be picked (a cross product of two edges would). Taken about the first
// vertex: the sums (a.z + b.z) would otherwise carry the distance from the origin and cancel.
Vec3 newellVector(const std::vector<Vec3>& v) {
  Vec3 sum = Vec3::Zero();
  const size_t n = v.size();
  if (n == 0) return sum;
  for (size_t i = 0; i < n; ++i) {
    const Vec3 a = v[i] - v[0];
    const Vec3 b = v[(i + 1) % n] - v[0];
    sum.x() += (a.y() - b.y()) * (a.z() + b.z());
    sum.y() += (a.z() - b.z()) * (a.x() + b.x());
    sum.z() += (a.x() - b.x()) * (a.y() + b.y());
  }
  return sum;
}

Vec3 vertexMean(const std::vector<Vec3>& v) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& p : v) sum += p;
  return v.empty() ? sum : Vec3(sum / static_cast<double>(v.size()));
}

}  // namespace

ConvexPolygon::ConvexPolygon(std::vector<Vec3> vertices) : vertices_(std::move(vertices)) {}

Vec3 ConvexPolygon::normal() const {
  const Vec3 n = newellVector(vertices_);
  const double length = n.norm();
  return length > 0.0 ? Vec3(n / length) : Vec3::Zero();
}

double ConvexPolygon::area() const {
  return 0.5 * newellVector(vertices_).norm();
}

Vec3 ConvexPolygon::centroid() const {
  if (empty()) return vertexMean(vertices_);
  // Fan from the first vertex; each triangle weighted by its area signed along the polygon's
  // normal, so that the weights add up to the area even for a (tolerated) collinear vertex.
  const Vec3 n = normal();
  const Vec3& apex = vertices_[0];
  Vec3 weighted = Vec3::Zero();
  double total = 0.0;
  for (int i = 1; i + 1 < size(); ++i) {
    const Vec3& b = vertices_[i];
    const Vec3& c = vertices_[i + 1];
    const double w = 0.5 * (b - apex).cross(c - apex).dot(n);
    weighted += w * (apex + b + c) / 3.0;
    total += w;
  }
  return total > 0.0 ? Vec3(weighted / total) : vertexMean(vertices_);
}

Plane ConvexPolygon::plane() const {
  // Through the vertex mean: Newell's plane, the least-squares fit for near-planar input.
  const Vec3 n = normal();
  return Plane{n, n.dot(vertexMean(vertices_))};
}

bool ConvexPolygon::isPlanar(double tolerance) const {
  if (empty() || area() <= 0.0) return false;
  const Plane p = plane();
  return std::all_of(vertices_.begin(), vertices_.end(),
                     [&](const Vec3& v) { return std::abs(p.signedDistance(v)) <= tolerance; });
}

bool ConvexPolygon::isConvex(double tolerance) const {
  if (empty() || area() <= 0.0) return false;
  // Every vertex must lie on the left of (or within tolerance of) the line of every edge, in
  // the polygon's own plane. Checking every vertex against every edge, rather than only the
  // turn at each vertex, also rejects loops that wind twice (a pentagram turns left
  // everywhere). Collinear vertices pass; polygons here have a handful of vertices.
  const Vec3 n = normal();
  const int count = size();
  for (int i = 0; i < count; ++i) {
    const Vec3& a = vertices_[i];
    const Vec3 edge = vertices_[(i + 1) % count] - a;
    const double length = edge.norm();
    if (length <= tolerance) continue;  // a repeated vertex defines no line to test against
    const Vec3 inward = n.cross(edge) / length;  // unit, in the plane, towards the interior
    for (const Vec3& v : vertices_) {
      if (inward.dot(v - a) < -tolerance) return false;
    }
  }
  return true;
}

ConvexPolygon ConvexPolygon::clipped(const Plane& boundary, double tolerance) const {
  if (empty()) return {};
  std::vector<double> distance(vertices_.size());
  bool allInside = true;
  bool anyInside = false;
  for (size_t i = 0; i < vertices_.size(); ++i) {
    distance[i] = boundary.signedDistance(vertices_[i]);
    allInside = allInside && distance[i] <= tolerance;
    anyInside = anyInside || distance[i] <= tolerance;
  }
  if (allInside) return *this;
  if (!anyInside) return {};

  // Sutherland-Hodgman against one plane. A vertex within tolerance counts as on the plane and
  // is kept as it is; an intersection is computed only for an edge running from strictly
  // inside to strictly outside, so it is never closer than `tolerance` to either end.
  std::vector<Vec3> kept;
  kept.reserve(vertices_.size() + 1);
  const size_t n = vertices_.size();
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    const double di = distance[i];
    const double dj = distance[j];
    if (di <= tolerance) kept.push_back(vertices_[i]);
    const bool crosses = (di < -tolerance && dj > tolerance) || (di > tolerance && dj < -tolerance);
    if (crosses) {
      const double t = di / (di - dj);
      kept.push_back(vertices_[i] + t * (vertices_[j] - vertices_[i]));
    }
  }
  if (kept.size() < 3) return {};
  return ConvexPolygon(std::move(kept));
}

ConvexPolygon ConvexPolygon::reversed() const {
  return ConvexPolygon(std::vector<Vec3>(vertices_.rbegin(), vertices_.rend()));
}

}  // namespace penumbra
