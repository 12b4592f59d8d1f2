// The direct light at the mesh's nodes and the refinement's measure (host/radiosity/node_light):
// evaluated in chunks of elements, with some or none of the chunks kept between its two passes,
// they are the values of one evaluation of every node at once, scaled by each source's flux onto
// the elements as the measure's definition states.
#include <gtest/gtest.h>

#include <fstream>

#include "radiosity/node_light.hpp"
#include "radiosity/radiosity_solver.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;

// A 6 × 4 × 3 m room lit by three panels of different colours and fluxes, a desk shading the
// floor.
Scene threePanelRoom(const TempDir& dir) {
  const auto file = dir.path() / "room.yaml";
  std::ofstream(file)
      << "penumbra: 1\nmaterials:\n  paint: 0.5\nroom:\n  size: [6, 4, 3]\n"
         "  materials: {floor: paint, ceiling: paint, walls: paint}\n"
         "sources:\n"
         "  - {name: a, rect: {center: [1.3, 1.7, 2.99], size: [0.6, 0.6], normal: [0, 0, -1]}, "
         "flux: 3000, color: [1.0, 0.8, 0.6]}\n"
         "  - {name: b, rect: {center: [4.5, 2.5, 2.99], size: [0.6, 0.6], normal: [0, 0, -1]}, "
         "flux: 1000}\n"
         "  - {name: c, rect: {center: [0.01, 2.0, 1.5], size: [0.5, 0.5], normal: [1, 0, 0]}, "
         "flux: 500, color: [0.6, 0.8, 1.0]}\n"
         "solids:\n  - {name: desk, box: {min: [1.0, 1.0, 0.7], max: [2.6, 1.8, 0.75]}, "
         "material: paint}\n";
  return loadScene(file);
}

TEST(NodeLight, ChunkedIsTheWholeEvaluationScaledByEachSourcesFlux) {
  TempDir dir("node-light");
  const Scene scene = threePanelRoom(dir);
  MeshOptions options;
  options.elementSize = 1.0;
  options.quadratureOrder = 3;
  const SurfaceMesh mesh = buildSurfaceMesh(scene, options);
  IlluminanceEngine engine(cpuDevice(), scene);

  // The reference: every node at once, each source's flux onto the elements the area-weighted
  // sum of its node-weighted element averages.
  const IlluminanceResult all = engine.evaluate(mesh.nodes, true);
  const auto sources = static_cast<std::size_t>(all.sourceCount);
  ASSERT_EQ(sources, 3u);
  std::vector<double> flux(sources, 0.0);
  for (std::size_t i = 0; i < mesh.elements.size(); ++i)
    for (std::size_t node = mesh.nodeStart[i]; node < mesh.nodeStart[i + 1]; ++node)
      for (std::size_t s = 0; s < sources; ++s)
        flux[s] += mesh.elements[i].area * mesh.weights[node] * all.bySource[node * sources + s];
  const auto n = static_cast<Eigen::Index>(mesh.nodes.size());
  Eigen::VectorXd balanced = Eigen::VectorXd::Zero(n);
  Eigen::MatrixX3d direct = Eigen::MatrixX3d::Zero(n, 3);
  for (Eigen::Index node = 0; node < n; ++node)
    for (std::size_t s = 0; s < sources; ++s) {
      const double e = all.bySource[static_cast<std::size_t>(node) * sources + s];
      balanced[node] += e / flux[s];
      const Vec3& color = scene.sources[s].color;
      direct.row(node) += e * (color / photometric(color)).transpose();
    }

  const std::size_t values = mesh.nodes.size() * sources;
  const NodeLightChunks one;                               // one chunk, kept
  const NodeLightChunks elementByElement{1, 0};            // a chunk per element, none kept
  const NodeLightChunks someKept{values / 5, values / 2};  // five chunks or so, two kept
  for (const NodeLightChunks& chunks : {one, elementByElement, someKept}) {
    const NodeLight light = nodeLight(engine, scene, mesh, {}, chunks);
    EXPECT_EQ(light.litGroups, 3.0);
    EXPECT_LE((light.direct - direct).cwiseAbs().maxCoeff(), 1e-12 * direct.cwiseAbs().maxCoeff());
    EXPECT_LE((light.balanced - balanced).cwiseAbs().maxCoeff(),
              1e-12 * balanced.cwiseAbs().maxCoeff());
  }
}

}  // namespace
}  // namespace penumbra
