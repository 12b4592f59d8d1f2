#pragma once
// Screen-space binning for primary visibility: each tile of PN_VISIBILITY_TILE² samples lists the
// objects whose projection may cover it, so that a sample tests a handful of solids, not all.
#include <vector>

#include "render/camera.hpp"
#include "render/visible_scene.hpp"

namespace penumbra {

struct ScreenTiles {
  int across = 0, down = 0;
  std::vector<int> start;    // per tile, into objects; one more entry than tiles (CSR)
  std::vector<int> objects;  // object indices, in scene order within each tile
};

// An object is binned by the bounding rectangle of its part in front of the eye (depth >
// minDepth, m): its vertices there and the points where its edges cross depth = minDepth. The
// rectangle is grown by one sample so that float rounding in the kernel never leaves a sample
// outside the tiles of an object it hits. Objects wholly behind the eye are in no tile.
ScreenTiles binObjects(const VisibleScene& scene, const Camera& camera, double minDepth);

}  // namespace penumbra
