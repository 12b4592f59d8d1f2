#include "radiosity/node_light.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <span>
#include <utility>

#include "engine/daylight_evaluation.hpp"
#include "radiosity/radiosity_solver.hpp"
#include "scene/daylight.hpp"

namespace penumbra {

namespace {

struct LightGroups {
  std::vector<Eigen::Vector3d> channel;  // per source: its colour over the colour's luminance
  std::size_t sources = 0;
  bool luminaires = false;
  std::vector<double> sky;  // lx per node, empty without the host's sky

  std::size_t count() const { return sources + (luminaires ? 1 : 0) + (sky.empty() ? 0 : 1); }
};

// Elements [first, last) of the mesh.
struct ElementRange {
  std::size_t first = 0, last = 0;
};

// E per light group at the nodes of `range` ([node − its first node][group], lx); with `direct`,
// those nodes' direct light per channel is added to it.
std::vector<double> groupLightOfRange(IlluminanceEngine& engine, const Scene& scene,
                                      const SurfaceMesh& mesh, const LightGroups& groups,
                                      ElementRange range, Eigen::MatrixX3d* direct) {
  const std::size_t firstNode = mesh.nodeStart[range.first];
  const std::span<const SamplePoint> nodes(mesh.nodes.data() + firstNode,
                                           mesh.nodeStart[range.last] - firstNode);
  const IlluminanceResult result = evaluateDaylight(engine, scene, nodes, true);
  const std::size_t count = groups.count(), sources = groups.sources;
  std::vector<double> byGroup(nodes.size() * count, 0.0);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    double* row = byGroup.data() + i * count;
    const auto node = static_cast<Eigen::Index>(firstNode + i);
    for (std::size_t s = 0; s < sources; ++s) {
      const double e = result.bySource[i * sources + s];
      row[s] = e;
      if (direct) direct->row(node) += e * groups.channel[s].transpose();
    }
    if (!result.luminaires.empty()) {
      const double e = result.luminaires[i];
      row[sources] = e;
      if (direct) direct->row(node).array() += e;
    }
    if (!groups.sky.empty()) {  // white, one more group after the luminaires
      const double e = groups.sky[firstNode + i];
      row[count - 1] = e;
      if (direct) direct->row(node).array() += e;
    }
  }
  return byGroup;
}

// The mesh's elements in chunks whose nodes × `groups` values stay within `values` (one element
// at least).
std::vector<ElementRange> elementChunks(const SurfaceMesh& mesh, std::size_t groups,
                                        std::size_t values) {
  std::vector<ElementRange> chunks;
  const std::size_t n = mesh.elements.size();
  for (std::size_t first = 0; first < n;) {
    std::size_t last = first + 1;
    while (last < n && (mesh.nodeStart[last + 1] - mesh.nodeStart[first]) * groups <= values)
      ++last;
    chunks.push_back(ElementRange{first, last});
    first = last;
  }
  return chunks;
}

}  // namespace

NodeLight nodeLight(IlluminanceEngine& engine, const Scene& scene, const SurfaceMesh& mesh,
                    const HostLight& host, const NodeLightChunks& sizes) {
  // The sources as the engine reports them: the scene's, then its sky's and ground's (white).
  const std::vector<Source> all = daylightScene(scene, 0.0).sources;
  LightGroups groups;
  groups.sources = all.size();
  for (const Source& source : all)
    groups.channel.push_back(source.color / photometric(source.color));
  groups.luminaires = !scene.luminaires.empty();
  const auto n = static_cast<Eigen::Index>(mesh.nodes.size());
  NodeLight light{Eigen::MatrixX3d::Zero(n, 3), Eigen::VectorXd::Zero(n), 0.0};
  if (n == 0) return light;
  if (host.sky) groups.sky = host.sky(mesh.nodes);
  const std::size_t count = groups.count();

  // First pass: the direct light, and each group's flux onto the elements (element by element in
  // mesh order, whatever the chunks).
  const std::vector<ElementRange> chunks = elementChunks(mesh, count, sizes.chunkValues);
  std::vector<std::vector<double>> kept;
  std::size_t keptValues = 0;
  std::vector<double> flux(count, 0.0), average(count);
  for (const ElementRange& range : chunks) {
    std::vector<double> byGroup =
        groupLightOfRange(engine, scene, mesh, groups, range, &light.direct);
    const std::size_t firstNode = mesh.nodeStart[range.first];
    for (std::size_t i = range.first; i < range.last; ++i) {
      std::fill(average.begin(), average.end(), 0.0);
      for (std::size_t node = mesh.nodeStart[i]; node < mesh.nodeStart[i + 1]; ++node)
        for (std::size_t g = 0; g < count; ++g)
          average[g] += mesh.weights[node] * byGroup[(node - firstNode) * count + g];
      for (std::size_t g = 0; g < count; ++g) flux[g] += average[g] * mesh.elements[i].area;
    }
    // The chunks kept are the first ones, up to the first that does not fit.
    if (kept.size() == static_cast<std::size_t>(&range - chunks.data()) &&
        keptValues + byGroup.size() <= sizes.keptValues) {
      keptValues += byGroup.size();
      kept.push_back(std::move(byGroup));
    }
  }
  std::vector<double> scale(count, 0.0);
  for (std::size_t g = 0; g < count; ++g)
    if (flux[g] > 0.0) scale[g] = 1.0 / flux[g], light.litGroups += 1.0;

  // Second pass: the groups at unit flux, summed.
  for (std::size_t c = 0; c < chunks.size(); ++c) {
    const std::vector<double> byGroup =
        c < kept.size() ? std::move(kept[c])
                        : groupLightOfRange(engine, scene, mesh, groups, chunks[c], nullptr);
    const std::size_t firstNode = mesh.nodeStart[chunks[c].first];
    const std::size_t nodes = mesh.nodeStart[chunks[c].last] - firstNode;
    for (std::size_t i = 0; i < nodes; ++i) {
      double sum = 0.0;
      for (std::size_t g = 0; g < count; ++g) sum += byGroup[i * count + g] * scale[g];
      light.balanced[static_cast<Eigen::Index>(firstNode + i)] = sum;
    }
  }
  return light;
}

std::vector<char> unevenElements(const SurfaceMesh& mesh, const NodeLight& light, double fraction,
                                 std::size_t maxElements, bool& capped) {
  const std::size_t n = mesh.elements.size();
  std::vector<std::pair<double, std::size_t>> uneven;  // (spread, element), above the bound
  for (std::size_t i = 0; i < n; ++i) {
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t node = mesh.nodeStart[i]; node < mesh.nodeStart[i + 1]; ++node) {
      const double e = light.balanced[static_cast<Eigen::Index>(node)];
      lo = std::min(lo, e), hi = std::max(hi, e);
    }
    const double spread = (hi - lo) * mesh.elements[i].area;
    if (spread > fraction * light.litGroups) uneven.emplace_back(spread, i);
  }
  const std::size_t room = maxElements > n ? (maxElements - n) / 3 : 0;
  if (uneven.size() > room) {
    capped = true;
    std::sort(uneven.begin(), uneven.end(), std::greater<>());  // ties: higher index first
    uneven.resize(room);
  }
  std::vector<char> split(n, 0);
  for (const auto& [spread, i] : uneven) split[i] = 1;
  return split;
}

}  // namespace penumbra
