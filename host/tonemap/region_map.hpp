#pragma once
// Regions from the face-id AOV: a region is one 4-connected visible part of one face (a face cut
// in two by an occluder gives two regions, each constrained to its own neighbours). Pixels with
// no surface belong to no region: they carry no constraint and are shown at their Space-3 value.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "image/images.hpp"

namespace penumbra {

struct RegionMap {
  static constexpr int32_t kNone = -1;
  int width = 0, height = 0;
  int count = 0;
  std::vector<int32_t> region;  // per pixel: region index, or kNone

  size_t index(int x, int y) const { return static_cast<size_t>(y) * width + x; }
  int32_t at(int x, int y) const { return region[index(x, y)]; }
};

RegionMap findRegions(const FaceIdImage& faces);

// Calls pair(i, j) once for every two 4-adjacent pixels of a width × height image (j the right or
// lower neighbour of i), in row order.
template <typename Pair>
void forEachAdjacentPair(int width, int height, Pair&& pair) {
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      if (x + 1 < width) pair(i, i + 1);
      if (y + 1 < height) pair(i, i + width);
    }
  }
}

}  // namespace penumbra
