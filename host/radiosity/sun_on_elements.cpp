#include "radiosity/sun_on_elements.hpp"

#include <vector>

#include "geometry/tolerance.hpp"

namespace penumbra {

Eigen::VectorXd sunElementAverage(const Scene& scene, const HostDirectLight& sun,
                                  const SurfaceMesh& mesh, const Eigen::VectorXd& nodeSun,
                                  int cellsPerSide) {
  const auto elements = static_cast<Eigen::Index>(mesh.elements.size());
  Eigen::VectorXd average = Eigen::VectorXd::Zero(elements);
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  // The cells' centres of the elements a patch edge crosses, each with its area fraction.
  std::vector<SamplePoint> centres;
  std::vector<double> weights;
  std::vector<Eigen::Index> owner;
  for (Eigen::Index i = 0; i < elements; ++i) {
    const std::size_t first = mesh.nodeStart[static_cast<std::size_t>(i)];
    const std::size_t last = mesh.nodeStart[static_cast<std::size_t>(i) + 1];
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t node = first; node < last; ++node) {
      const double e = nodeSun[static_cast<Eigen::Index>(node)];
      average[i] += mesh.weights[node] * e;
      lo = std::min(lo, e), hi = std::max(hi, e);
    }
    if (first == last || lo == hi) continue;
    const SurfaceElement& element = mesh.elements[static_cast<std::size_t>(i)];
    const double size = longestEdge(element.polygon) / cellsPerSide;
    const SamplePoint& node = mesh.nodes[first];
    for (const ConvexPolygon& cell : cutIntoCells(element.polygon, size, tolerance)) {
      centres.push_back({cell.centroid(), node.normal, node.solid});
      weights.push_back(cell.area() / element.area);
      owner.push_back(i);
    }
    average[i] = 0.0;
  }
  const std::vector<double> e = sun(centres);
  for (std::size_t k = 0; k < e.size(); ++k) average[owner[k]] += weights[k] * e[k];
  return average;
}

}  // namespace penumbra
