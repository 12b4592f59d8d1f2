#include "radiosity/element_transfer.hpp"

#include <algorithm>

namespace penumbra {

Scene elementScene(const Scene& scene, const SurfaceMesh& mesh) {
  Scene elements;
  elements.file = scene.file;
  elements.materials = scene.materials;
  elements.solids = scene.solids;
  elements.room = scene.room;
  elements.sources.reserve(mesh.elements.size());
  for (std::size_t i = 0; i < mesh.elements.size(); ++i) {
    Source source;
    source.name = "element-" + std::to_string(i);
    source.faces = {mesh.elements[i].polygon};
    source.luminance = 1.0;
    elements.sources.push_back(std::move(source));
  }
  return elements;
}

Eigen::MatrixXd elementTransfer(IlluminanceEngine& engine, const SurfaceMesh& mesh) {
  const auto n = static_cast<Eigen::Index>(mesh.elements.size());
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(n, n);
  if (n == 0) return t;
  // Whole elements per batch, about 2^22 node·element values (16 MB of float) at a time.
  const std::size_t budget = std::size_t{1} << 22;
  std::size_t first = 0;
  while (first < mesh.elements.size()) {
    std::size_t last = first + 1;
    while (last < mesh.elements.size() &&
           (mesh.nodeStart[last + 1] - mesh.nodeStart[first]) * mesh.elements.size() <= budget)
      ++last;
    const std::size_t begin = mesh.nodeStart[first], end = mesh.nodeStart[last];
    std::size_t stride = 0;
    const std::vector<float> e = engine.illuminanceBySource(
        std::span<const SamplePoint>(mesh.nodes).subspan(begin, end - begin), stride);
    for (Eigen::Index j = 0; j < n; ++j) {
      const float* row = e.data() + static_cast<std::size_t>(j) * stride;
      for (std::size_t i = first; i < last; ++i) {
        double sum = 0.0;
        for (std::size_t node = mesh.nodeStart[i]; node < mesh.nodeStart[i + 1]; ++node)
          sum += mesh.weights[node] * row[node - begin];
        t(static_cast<Eigen::Index>(i), j) = sum;
      }
    }
    first = last;
  }
  return t;
}

}  // namespace penumbra
