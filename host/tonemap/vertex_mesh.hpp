#pragma once
// The variables of the constraint problem: vertices at pixel centres, each in one region.
// A region's vertices lie on an interior lattice (every `lattice` pixels in x and y, plus the last
// column and row) and along its boundary, where a boundary pixel (one with a 4-neighbour in
// another region) is a vertex on every lattice column and lattice row it lies on. A straight edge
// therefore has vertices at most `lattice` pixels apart on both sides, so that a penumbra gradient
// or a long edge is represented, and the number of variables stays near pixels / lattice².
// A region too small to hold any such pixel gets its first pixel as its one vertex.
#include <cstdint>
#include <vector>

#include "tonemap/region_map.hpp"

namespace penumbra {

struct MeshVertex {
  int x = 0, y = 0;
  int32_t region = 0;
  bool boundary = false;
};

struct VertexMesh {
  static constexpr int32_t kNone = -1;
  int lattice = 0;
  std::vector<MeshVertex> vertices;
  std::vector<int32_t> vertexAt;  // per pixel: vertex index, or kNone
};

VertexMesh buildVertexMesh(const RegionMap& regions, int lattice);

// True when the pixel has a 4-neighbour in another region (or in no region).
bool onRegionBoundary(const RegionMap& regions, int x, int y);

}  // namespace penumbra
