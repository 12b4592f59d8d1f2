#include "tonemap/vertex_gain_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

namespace penumbra {
namespace {

// One standard deviation of the range weight is a Space-0 ratio of e^0.5 ≈ 1.65; beyond 3σ a
// vertex does not count (its weight would be below 1e-4 of a like one's).
constexpr double kRangeSigma = 0.5;
constexpr double kRangeCutoff2 = 9 * kRangeSigma * kRangeSigma;

struct PixelSums {
  float weight = 0, weightedGain = 0;
  float closest = std::numeric_limits<float>::infinity(), closestGain = 0;
};

}  // namespace

ScalarImage interpolateDisplayValues(const VertexMesh& mesh, const RegionMap& regions,
                                     const DisplaySpaces& spaces, const LogScene& scene,
                                     const Eigen::VectorXd& values) {
  const int width = regions.width, height = regions.height, spacing = mesh.lattice;
  const size_t count = regions.region.size();
  const std::vector<float>& logV0 = scene.logValue;
  std::vector<double> regionValue(regions.count, 0.0), regionVertices(regions.count, 0.0);
  std::vector<PixelSums> sums(count);
  // Splat each vertex over its tent, onto pixels of its own region only: the work is
  // vertices × (2·lattice - 1)², not pixels × window.
  for (size_t v = 0; v < mesh.vertices.size(); ++v) {
    const MeshVertex& vertex = mesh.vertices[v];
    const size_t at = regions.index(vertex.x, vertex.y);
    const float gain = static_cast<float>(values[v] - logV0[at]);
    regionValue[vertex.region] += values[v];
    regionVertices[vertex.region] += 1;
    for (int y = std::max(0, vertex.y - spacing + 1);
         y <= std::min(height - 1, vertex.y + spacing - 1); ++y) {
      const float wy = 1.0f - float(std::abs(y - vertex.y)) / spacing;
      for (int x = std::max(0, vertex.x - spacing + 1);
           x <= std::min(width - 1, vertex.x + spacing - 1); ++x) {
        const size_t i = regions.index(x, y);
        if (regions.region[i] != vertex.region) continue;
        const float d = logV0[i] - logV0[at];
        PixelSums& s = sums[i];
        if (std::abs(d) < s.closest) s.closest = std::abs(d), s.closestGain = gain;
        if (d * d > kRangeCutoff2) continue;
        const float w = wy * (1.0f - float(std::abs(x - vertex.x)) / spacing) *
                        std::exp(-d * d / float(2 * kRangeSigma * kRangeSigma));
        s.weight += w;
        s.weightedGain += w * gain;
      }
    }
  }
  ScalarImage display(width, height);
  for (size_t i = 0; i < count; ++i) {
    const int32_t r = regions.region[i];
    double value;
    if (r == RegionMap::kNone) {
      value = scene.exposedValue(i);
    } else if (mesh.vertexAt[i] != VertexMesh::kNone) {
      value = values[mesh.vertexAt[i]];
    } else if (sums[i].weight > 0) {
      value = logV0[i] + sums[i].weightedGain / sums[i].weight;
    } else if (std::isfinite(sums[i].closest)) {
      value = logV0[i] + sums[i].closestGain;
    } else {
      value = regionValue[r] / regionVertices[r];
    }
    display.values[i] = boundedDisplayValue(std::exp(value), spaces.lowerBound);
  }
  return display;
}

}  // namespace penumbra
