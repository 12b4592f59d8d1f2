#include "reference/pyramid_oracle.hpp"

#include <algorithm>
#include <limits>
#include <vector>

namespace penumbra {

namespace {

struct Extent {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
};

Extent extent(const Vec3& axis, std::span<const Vec3> points) {
  Extent e;
  for (const Vec3& p : points) {
    const double d = axis.dot(p);
    e.lo = std::min(e.lo, d);
    e.hi = std::max(e.hi, d);
  }
  return e;
}

}  // namespace

double separation(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  std::vector<Vec3> axes;
  for (const auto& f : a.faces()) axes.push_back(f.plane.normal);
  for (const auto& f : b.faces()) axes.push_back(f.plane.normal);
  for (const auto& ea : a.edges()) {
    const Vec3 da = a.vertices()[ea.to] - a.vertices()[ea.from];
    for (const auto& eb : b.edges())
      axes.push_back(da.cross(b.vertices()[eb.to] - b.vertices()[eb.from]));
  }
  double best = -std::numeric_limits<double>::infinity();
  for (const Vec3& axis : axes) {
    const double length = axis.norm();
    if (!(length > 1e-300)) continue;
    const Vec3 unit = axis / length;
    const Extent ea = extent(unit, a.vertices());
    const Extent eb = extent(unit, b.vertices());
    best = std::max(best, std::max(eb.lo - ea.hi, ea.lo - eb.hi));
  }
  return best;
}

double pyramidSeparation(const Vec3& apex, std::span<const Vec3> source, const ConvexPolyhedron& v,
                         double tolerance) {
  std::vector<Vec3> points{apex};
  points.insert(points.end(), source.begin(), source.end());
  const ConvexPolyhedron pyramid = ConvexPolyhedron::hull(points, tolerance);
  if (pyramid.empty()) return std::numeric_limits<double>::infinity();
  return separation(pyramid, v);
}

bool segmentClears(const Vec3& a, const Vec3& b, const ConvexPolyhedron& v, double margin) {
  // Cyrus–Beck: the part of a + t (b − a), t in [0, 1], inside every grown face plane.
  double t0 = 0.0, t1 = 1.0;
  const Vec3 d = b - a;
  for (const auto& f : v.faces()) {
    const double start = f.plane.signedDistance(a) - margin;
    const double rate = f.plane.normal.dot(d);
    if (rate == 0.0) {
      if (start > 0.0) return true;
      continue;
    }
    const double t = -start / rate;
    if (rate > 0.0)
      t1 = std::min(t1, t);
    else
      t0 = std::max(t0, t);
    if (t0 > t1) return true;
  }
  return false;
}

}  // namespace penumbra
