#include "tonemap/vertex_gain_field.hpp"

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace penumbra {

ScalarImage interpolateDisplayValues(const VertexMesh& mesh, const RegionMap& regions,
                                     const DisplaySpaces& spaces, const Eigen::VectorXd& values) {
  const int width = regions.width, height = regions.height, spacing = mesh.lattice;
  const size_t count = regions.region.size();
  std::vector<double> weighted(count, 0.0), weights(count, 0.0);
  std::vector<double> regionGain(regions.count, 0.0), regionVertices(regions.count, 0.0);
  std::vector<double> gain(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    const MeshVertex& vertex = mesh.vertices[v];
    gain[v] = values[v] / spaces.value3[spaces.index(vertex.x, vertex.y)];
    regionGain[vertex.region] += gain[v];
    regionVertices[vertex.region] += 1;
  }
  // Splat each vertex's gain over its tent, onto pixels of its own region only: the work is
  // vertices × (2·lattice - 1)², not pixels × window.
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    const MeshVertex& vertex = mesh.vertices[v];
    for (int y = std::max(0, vertex.y - spacing + 1);
         y <= std::min(height - 1, vertex.y + spacing - 1); ++y) {
      const double wy = 1.0 - double(std::abs(y - vertex.y)) / spacing;
      for (int x = std::max(0, vertex.x - spacing + 1);
           x <= std::min(width - 1, vertex.x + spacing - 1); ++x) {
        const size_t i = regions.index(x, y);
        if (regions.region[i] != vertex.region) continue;
        const double w = wy * (1.0 - double(std::abs(x - vertex.x)) / spacing);
        weighted[i] += w * gain[v];
        weights[i] += w;
      }
    }
  }
  ScalarImage display(width, height);
  const double lb = spaces.lowerBound;
  for (size_t i = 0; i < count; ++i) {
    const int32_t r = regions.region[i];
    double value;
    if (r == RegionMap::kNone) {
      value = spaces.value3[i];
    } else if (mesh.vertexAt[i] != VertexMesh::kNone) {
      value = values[mesh.vertexAt[i]];
    } else {
      const double g =
          weights[i] > 0 ? weighted[i] / weights[i] : regionGain[r] / regionVertices[r];
      value = spaces.value3[i] * g;
    }
    display.values[i] = boundedDisplayValue(value, lb);
  }
  return display;
}

}  // namespace penumbra
