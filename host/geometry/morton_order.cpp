#include "geometry/morton_order.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>

namespace penumbra {

namespace {

// Spreads the low 21 bits of v to every third bit.
std::uint64_t spreadBits(std::uint64_t v) {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffff;
  v = (v | v << 16) & 0x1f0000ff0000ff;
  v = (v | v << 8) & 0x100f00f00f00f00f;
  v = (v | v << 4) & 0x10c30c30c30c30c3;
  v = (v | v << 2) & 0x1249249249249249;
  return v;
}

}  // namespace

// The points in Morton (Z-curve) order of their positions, in cubic cells over the points'
// bounding box. A work-item takes PN_LANES consecutive points, and the patch table lists a
// face's casters for boxes of consecutive work-items (patch_table.cpp): compact runs of points
// keep those boxes small. In a grid's own order a group of 128 points is a strip as long as the
// room, whose list holds every caster along it.
std::vector<std::size_t> mortonOrder(std::span<const SamplePoint> points) {
  Vec3 lo = points[0].position, hi = lo;
  for (const SamplePoint& p : points) {
    lo = lo.cwiseMin(p.position);
    hi = hi.cwiseMax(p.position);
  }
  const double extent = (hi - lo).maxCoeff();
  const double cells = double{1 << 21} - 1.0;
  const double scale = extent > 0.0 ? cells / extent : 0.0;
  std::vector<std::pair<std::uint64_t, std::size_t>> keys(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 q = (points[i].position - lo) * scale;
    std::uint64_t key = 0;
    for (int k = 0; k < 3; ++k)
      key |= spreadBits(static_cast<std::uint64_t>(std::clamp(q[k], 0.0, cells))) << k;
    keys[i] = {key, i};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::size_t> order(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) order[i] = keys[i].second;
  return order;
}

}  // namespace penumbra
