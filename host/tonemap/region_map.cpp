#include "tonemap/region_map.hpp"

namespace penumbra {

RegionMap findRegions(const FaceIdImage& faces) {
  RegionMap map;
  map.width = faces.width;
  map.height = faces.height;
  map.region.assign(faces.ids.size(), RegionMap::kNone);
  std::vector<size_t> stack;
  for (size_t seed = 0; seed < faces.ids.size(); ++seed) {
    if (faces.ids[seed] == FaceIdImage::kNoSurface || map.region[seed] != RegionMap::kNone) {
      continue;
    }
    // Flood fill with an explicit stack: a wall can cover most of a 4K image.
    const int32_t label = map.count++;
    const uint32_t id = faces.ids[seed];
    map.region[seed] = label;
    stack.push_back(seed);
    while (!stack.empty()) {
      const size_t i = stack.back();
      stack.pop_back();
      const int x = static_cast<int>(i % faces.width), y = static_cast<int>(i / faces.width);
      const auto visit = [&](int nx, int ny) {
        const size_t n = map.index(nx, ny);
        if (faces.ids[n] == id && map.region[n] == RegionMap::kNone) {
          map.region[n] = label;
          stack.push_back(n);
        }
      };
      if (x > 0) visit(x - 1, y);
      if (x + 1 < faces.width) visit(x + 1, y);
      if (y > 0) visit(x, y - 1);
      if (y + 1 < faces.height) visit(x, y + 1);
    }
  }
  return map;
}

}  // namespace penumbra
