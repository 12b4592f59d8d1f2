// The hierarchical transfer (host/radiosity/hierarchical_transfer): with no error allowed its
// links are the dense element-to-element matrix entry for entry; with the default bound its
// solution stays within the bound's reach of the dense one on the same elements, and tightens as
// the bound does; a closed room conserves energy; the links grow far slower than the element
// pairs.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <numbers>

#include "geometry/tolerance.hpp"
#include "radiosity/element_transfer.hpp"
#include "radiosity/hierarchical_transfer.hpp"
#include "radiosity/interreflection.hpp"
#include "radiosity/radiosity_solver.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;
constexpr double kPi = std::numbers::pi;

// A 6 × 4 × 3 m room of one paint (ρ), a ceiling panel and a desk and a cabinet that shade.
Scene furnishedRoom(const TempDir& dir, double rho) {
  const auto file = dir.path() / "room.yaml";
  std::ofstream(file)
      << "penumbra: 1\nmaterials:\n  paint: " << rho
      << "\nroom:\n  size: [6, 4, 3]\n"
         "  materials: {floor: paint, ceiling: paint, walls: paint}\n"
         "sources:\n  - {name: panel, rect: {center: [1.3, 1.7, 2.99], size: [0.6, 0.6], "
         "normal: [0, 0, -1]}, flux: 3000}\n"
         "solids:\n  - {name: desk, box: {min: [1.0, 1.0, 0.7], max: [2.6, 1.8, 0.75]}, "
         "material: paint}\n"
         "  - {name: cabinet, box: {min: [4.0, 0.2, 0.0], max: [5.8, 0.8, 1.8]}, "
         "material: paint}\n";
  return loadScene(file);
}

std::vector<SamplePoint> workPlane() {
  std::vector<SamplePoint> points;
  for (double x = 0.25; x < 6.0; x += 0.5)
    for (double y = 0.25; y < 4.0; y += 0.5)
      points.push_back(SamplePoint{Vec3(x, y, 0.8), Vec3::UnitZ(), -1});
  return points;
}

TEST(HierarchicalTransfer, WithNoErrorAllowedTheLinksAreTheDenseMatrix) {
  TempDir dir("hierarchy-dense");
  const Scene scene = furnishedRoom(dir, 0.5);
  const ElementTree tree = buildElementTree(scene, 1.0);
  const SurfaceMesh leaves = tree.leafMesh(3);
  const Scene elements = elementScene(scene, leaves);
  IlluminanceEngine engine(cpuDevice(), elements);
  const Eigen::MatrixXd dense = elementTransfer(engine, leaves);

  // Every link joins two leaves, and each pair that exchanges light has its link: with each
  // node's own casters, the dense matrix's floats; with casters shared (the default), the same
  // within the kernel's bound (the unit hemisphere gives π lx), as extra candidates change only
  // the rounding.
  for (bool share : {false, true}) {
    HierarchyOptions options;
    options.linkError = 0.0;
    options.quadratureOrder = 3;
    options.shareCasters = share;
    const HierarchicalTransfer links(cpuDevice(), scene, tree, options, {});
    const NodeLinks& l = links.links();
    Eigen::MatrixXd linked = Eigen::MatrixXd::Zero(dense.rows(), dense.cols());
    for (std::size_t p = 0; p < tree.nodes.size(); ++p)
      for (std::size_t k = l.start[p]; k < l.start[p + 1]; ++k) {
        ASSERT_TRUE(tree.nodes[p].isLeaf() && tree.nodes[l.source[k]].isLeaf());
        linked(tree.nodes[p].leaf, tree.nodes[l.source[k]].leaf) = l.transfer[k];
      }
    const double worst = (linked - dense).cwiseAbs().maxCoeff();
    std::printf("casters %s: largest difference from the dense matrix %.2e lx per cd/m2\n",
                share ? "shared" : "own", worst);
    EXPECT_LE(worst, (share ? Tolerance::kKernelRelative : 1e-12) * kPi);
  }
}

TEST(HierarchicalTransfer, SolutionApproachesTheDenseOneAsTheBoundTightens) {
  TempDir dir("hierarchy-bound");
  const Scene scene = furnishedRoom(dir, 0.7);
  IlluminanceEngine direct(cpuDevice(), scene);
  const std::vector<SamplePoint> points = workPlane();

  // The dense solve on the same elements (the tree's leaves) is the reference.
  MeshOptions exact;
  exact.elementSize = 0.5;
  exact.linkError = 1e-30;  // a bound no link meets: every link joins two leaves
  Interreflection reference(cpuDevice(), scene, direct, exact);
  const Scene elements = elementScene(scene, reference.mesh());
  IlluminanceEngine engine(cpuDevice(), elements);
  const RadiositySolution dense = solveRadiosity(elementTransfer(engine, reference.mesh()),
                                                 reference.mesh(), reference.direct());
  EXPECT_LE((reference.solution().luminance - dense.luminance).norm(),
            1e-8 * dense.luminance.norm());
  const std::vector<double> e0 = reference.indirect(points);

  double previous = INFINITY;
  std::size_t previousLinks = 0;
  for (double bound : {2e-3, 2e-4, 2e-5}) {
    MeshOptions mesh = exact;
    mesh.linkError = bound;
    Interreflection solved(cpuDevice(), scene, direct, mesh);
    ASSERT_EQ(solved.mesh().elements.size(), reference.mesh().elements.size());
    const std::vector<double> e = solved.indirect(points);
    double worst = 0.0, mean = 0.0;
    for (double v : e0) mean += v / static_cast<double>(e0.size());
    for (std::size_t i = 0; i < e.size(); ++i) worst = std::max(worst, std::abs(e[i] - e0[i]));
    worst /= mean;
    // The link bound is relative to π lx per cd/m²: the work plane's error is of its order.
    EXPECT_LT(worst, 10.0 * bound) << bound;
    EXPECT_LT(worst, previous) << bound;
    EXPECT_GT(solved.report().links, previousLinks) << bound;
    EXPECT_LE(solved.report().residual, 1e-9);
    previous = worst;
    previousLinks = solved.report().links;
  }
}

TEST(HierarchicalTransfer, ClosedRoomConservesEnergy) {
  TempDir dir("hierarchy-energy");
  for (double rho : {0.5, 0.95}) {
    const Scene scene = furnishedRoom(dir, rho);
    IlluminanceEngine direct(cpuDevice(), scene);
    MeshOptions mesh;
    mesh.linkError = 2e-4;
    const Interreflection solved(cpuDevice(), scene, direct, mesh);
    // Area averages over every surface: indirect = ρ/(1 - ρ) · direct (CIE 171 case 5.8's
    // relation), each element's E from the solve.
    double direct_flux = 0.0, indirect_flux = 0.0;
    const SurfaceMesh& m = solved.mesh();
    for (std::size_t i = 0; i < m.elements.size(); ++i) {
      direct_flux += m.elements[i].area * photometric(solved.direct().row(i).transpose());
      indirect_flux +=
          m.elements[i].area * photometric(solved.solution().indirect.row(i).transpose());
    }
    EXPECT_NEAR(indirect_flux / direct_flux, rho / (1.0 - rho), 1e-4 * rho / (1.0 - rho)) << rho;
  }
}

}  // namespace
}  // namespace penumbra
