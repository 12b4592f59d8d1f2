#include "tonemap/vertex_mesh.hpp"

#include <stdexcept>

namespace penumbra {

bool onRegionBoundary(const RegionMap& regions, int x, int y) {
  const int32_t r = regions.at(x, y);
  return (x > 0 && regions.at(x - 1, y) != r) ||
         (x + 1 < regions.width && regions.at(x + 1, y) != r) ||
         (y > 0 && regions.at(x, y - 1) != r) ||
         (y + 1 < regions.height && regions.at(x, y + 1) != r);
}

VertexMesh buildVertexMesh(const RegionMap& regions, int lattice) {
  if (lattice < 1) throw std::invalid_argument("the lattice spacing must be at least 1 pixel");
  VertexMesh mesh;
  mesh.lattice = lattice;
  mesh.vertexAt.assign(regions.region.size(), VertexMesh::kNone);
  std::vector<bool> hasVertex(regions.count, false);
  for (int y = 0; y < regions.height; ++y) {
    const bool latticeRow = y % lattice == 0 || y == regions.height - 1;
    for (int x = 0; x < regions.width; ++x) {
      const int32_t r = regions.at(x, y);
      if (r == RegionMap::kNone) continue;
      const bool latticeColumn = x % lattice == 0 || x == regions.width - 1;
      const bool boundary = onRegionBoundary(regions, x, y);
      if ((latticeRow && latticeColumn) || (boundary && (latticeRow || latticeColumn))) {
        mesh.vertexAt[regions.index(x, y)] = static_cast<int32_t>(mesh.vertices.size());
        mesh.vertices.push_back({x, y, r, boundary});
        hasVertex[r] = true;
      }
    }
  }
  for (size_t i = 0; i < regions.region.size(); ++i) {
    const int32_t r = regions.region[i];
    if (r == RegionMap::kNone || hasVertex[r]) continue;
    const int x = static_cast<int>(i % regions.width), y = static_cast<int>(i / regions.width);
    mesh.vertexAt[i] = static_cast<int32_t>(mesh.vertices.size());
    mesh.vertices.push_back({x, y, r, onRegionBoundary(regions, x, y)});
    hasVertex[r] = true;
  }
  return mesh;
}

}  // namespace penumbra
