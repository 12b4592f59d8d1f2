#include "viz/polygon2d.hpp"

#include <algorithm>

namespace penumbra::viz {

namespace {

using V2 = Eigen::Vector2d;

// > 0 when b is left of o → a.
double turn(const V2& o, const V2& a, const V2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

Polygon2 clipLeftOf(const Polygon2& polygon, const V2& from, const V2& to) {
  Polygon2 kept;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const V2& a = polygon[i];
    const V2& b = polygon[(i + 1) % polygon.size()];
    const double sa = turn(from, to, a), sb = turn(from, to, b);
    if (sa >= 0) kept.push_back(a);
    if ((sa >= 0) != (sb >= 0)) kept.push_back(a + sa / (sa - sb) * (b - a));
  }
  return kept;
}

Polygon2 clipToBox(const Polygon2& polygon, const V2& lo, const V2& hi) {
  const Polygon2 box{lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};
  Polygon2 clipped = polygon;
  for (std::size_t i = 0; i < box.size() && clipped.size() >= 3; ++i) {
    clipped = clipLeftOf(clipped, box[i], box[(i + 1) % box.size()]);
  }
  if (clipped.size() < 3) clipped.clear();
  return clipped;
}

double signedArea(const Polygon2& polygon) {
  double twice = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    twice += turn(V2::Zero(), polygon[i], polygon[(i + 1) % polygon.size()]);
  }
  return twice / 2.0;
}

Polygon2 convexHull(Polygon2 points) {
  std::sort(points.begin(), points.end(), [](const V2& a, const V2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (points.size() < 3) return {};
  Polygon2 hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i > 0; --i) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i - 1]) <= 0) --k;
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace penumbra::viz
