#include "geometry/morton_order.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>

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

// Sorts `order` (and `keys` with it) by ascending key, equal keys keeping their order: a least
// significant digit first radix sort, one stable counting pass per byte in which the keys differ
// (a grid batch's keys share their high bytes). Linear in the points, where a comparison sort
// of a 65 536-point batch costs as much as building its patch table.
void radixSortByKey(std::vector<std::uint64_t>& keys, std::vector<std::size_t>& order) {
  if (keys.empty()) return;
  std::uint64_t differing = 0;
  for (std::uint64_t key : keys) differing |= key ^ keys.front();
  std::vector<std::uint64_t> keysTo(keys.size());
  std::vector<std::size_t> orderTo(order.size());
  for (int shift = 0; shift < 64; shift += 8) {
    if (((differing >> shift) & 0xff) == 0) continue;
    std::size_t start[257] = {};
    for (std::uint64_t key : keys) ++start[((key >> shift) & 0xff) + 1];
    for (int digit = 0; digit < 256; ++digit) start[digit + 1] += start[digit];
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const std::size_t to = start[(keys[i] >> shift) & 0xff]++;
      keysTo[to] = keys[i];
      orderTo[to] = order[i];
    }
    keys.swap(keysTo);
    order.swap(orderTo);
  }
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
  // Each point's key depends on that point alone: computed in parallel, the same keys.
  std::vector<std::uint64_t> keys(points.size());
  std::vector<std::size_t> order(points.size());
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, points.size(), 4096),
      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          const Vec3 q = (points[i].position - lo) * scale;
          std::uint64_t key = 0;
          for (int k = 0; k < 3; ++k)
            key |= spreadBits(static_cast<std::uint64_t>(std::clamp(q[k], 0.0, cells))) << k;
          keys[i] = key;
          order[i] = i;
        }
      });
  radixSortByKey(keys, order);
  return order;
}

}  // namespace penumbra
