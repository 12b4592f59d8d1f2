#pragma once
#include <limits>

#include "geometry/vec.hpp"

namespace penumbra {

// An axis-aligned box; empty (lo > hi) until a point is added.
struct BoundingBox {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());

  void add(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool empty() const { return (lo.array() > hi.array()).any(); }
  BoundingBox grown(double margin) const {
    return BoundingBox{lo - Vec3::Constant(margin), hi + Vec3::Constant(margin)};
  }
  bool overlaps(const BoundingBox& other) const {
    return (lo.array() <= other.hi.array()).all() && (other.lo.array() <= hi.array()).all();
  }
  bool contains(const BoundingBox& other) const {
    return (lo.array() <= other.lo.array()).all() && (other.hi.array() <= hi.array()).all();
  }
};

}  // namespace penumbra
