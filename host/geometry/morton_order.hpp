#pragma once
// Points in Morton (Z-curve) order: consecutive points stay close together, so a group of them
// has a small bounding box (the kernel's work-items and the patch tables' boxes rely on it).
#include <span>
#include <vector>

#include "geometry/sample_point.hpp"

namespace penumbra {

// The indices of `points` in Morton order of their positions, in cubic cells over the points'
// bounding box.
std::vector<std::size_t> mortonOrder(std::span<const SamplePoint> points);

}  // namespace penumbra
