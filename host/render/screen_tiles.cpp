#include "render/screen_tiles.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace penumbra {
namespace {

struct TileRange {
  int x0, y0, x1, y1;  // inclusive
};

std::optional<TileRange> coveredTiles(const std::vector<Vec3>& vertices,
                                      const std::vector<std::pair<int, int>>& edges,
                                      const Camera& camera, double minDepth, int across, int down) {
  Eigen::Vector2d low(INFINITY, INFINITY), high(-INFINITY, -INFINITY);
  bool any = false;
  const auto add = [&](const Vec3& p, double depth) {
    // On the cut (depth = minDepth) the projection is taken just in front of it.
    const std::optional<Eigen::Vector2d> s = camera.project(p, std::min(depth, minDepth) * 0.5);
    if (!s) return;
    low = low.cwiseMin(*s);
    high = high.cwiseMax(*s);
    any = true;
  };
  for (const Vec3& v : vertices) {
    const double depth = camera.depth(v);
    if (depth > minDepth) add(v, minDepth);
  }
  for (const auto& [a, b] : edges) {
    const double da = camera.depth(vertices[a]) - minDepth;
    const double db = camera.depth(vertices[b]) - minDepth;
    if ((da > 0.0) == (db > 0.0)) continue;
    const Vec3 crossing = vertices[a] + (vertices[b] - vertices[a]) * (da / (da - db));
    add(crossing, minDepth);
  }
  if (!any) return std::nullopt;
  const double tile = PN_VISIBILITY_TILE;
  const auto clampTile = [](double v, int count) {
    return static_cast<int>(std::clamp(std::floor(v), 0.0, static_cast<double>(count - 1)));
  };
  // One sample of margin on each side.
  if (high.x() < -1.0 || high.y() < -1.0 || low.x() > camera.width + 1.0 ||
      low.y() > camera.height + 1.0) {
    return std::nullopt;
  }
  return TileRange{
      clampTile((low.x() - 1.0) / tile, across), clampTile((low.y() - 1.0) / tile, down),
      clampTile((high.x() + 1.0) / tile, across), clampTile((high.y() + 1.0) / tile, down)};
}

}  // namespace

ScreenTiles binObjects(const VisibleScene& scene, const Camera& camera, double minDepth) {
  ScreenTiles tiles;
  tiles.across = (camera.width + PN_VISIBILITY_TILE - 1) / PN_VISIBILITY_TILE;
  tiles.down = (camera.height + PN_VISIBILITY_TILE - 1) / PN_VISIBILITY_TILE;
  const int count = tiles.across * tiles.down;
  std::vector<std::optional<TileRange>> ranges(scene.objects.size());
  std::vector<int> perTile(count, 0);
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    ranges[o] =
        coveredTiles(scene.vertices[o], scene.edges[o], camera, minDepth, tiles.across, tiles.down);
    if (!ranges[o]) continue;
    for (int y = ranges[o]->y0; y <= ranges[o]->y1; ++y)
      for (int x = ranges[o]->x0; x <= ranges[o]->x1; ++x) ++perTile[y * tiles.across + x];
  }
  tiles.start.assign(count + 1, 0);
  for (int t = 0; t < count; ++t) tiles.start[t + 1] = tiles.start[t] + perTile[t];
  tiles.objects.resize(tiles.start.back());
  std::vector<int> next(tiles.start.begin(), tiles.start.end() - 1);
  // Objects in scene order within each tile: the kernel's tie rule depends on it.
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    if (!ranges[o]) continue;
    for (int y = ranges[o]->y0; y <= ranges[o]->y1; ++y)
      for (int x = ranges[o]->x0; x <= ranges[o]->x1; ++x)
        tiles.objects[next[y * tiles.across + x]++] = static_cast<int>(o);
  }
  return tiles;
}

}  // namespace penumbra
