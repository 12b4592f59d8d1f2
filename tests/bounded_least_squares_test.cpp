// The sparse primal-dual active-set solver against the dense primal active-set oracle, on random
// problems and on the tone map's own small meshes, with and without bounds in play.
#include "tonemap/bounded_least_squares.hpp"

#include <gtest/gtest.h>

#include <random>

#include "dense_bounded_least_squares.hpp"
#include "synthetic_images.hpp"
#include "tonemap/constraint_system.hpp"
#include "tonemap/display_spaces.hpp"
#include "tonemap/region_map.hpp"
#include "tonemap/vertex_mesh.hpp"

namespace penumbra {
namespace {

using SparseRows = Eigen::SparseMatrix<double, Eigen::RowMajor>;

TEST(BoundedLeastSquares, UnboundedOptimumIsTheLeastSquaresSolution) {
  // Bounds far away: the answer is the plain least-squares solution (QR of A).
  std::mt19937 random(3);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd a(30, 12);
  for (Eigen::Index i = 0; i < a.size(); ++i) a.data()[i] = normal(random);
  Eigen::VectorXd b(30);
  for (Eigen::Index i = 0; i < b.size(); ++i) b[i] = normal(random);
  const Eigen::VectorXd expected = a.colPivHouseholderQr().solve(b);
  const SparseRows sparse = a.sparseView();
  const auto result =
      solveBoundedLeastSquares(sparse, b, Eigen::VectorXd::Constant(12, -1e6),
                               Eigen::VectorXd::Constant(12, 1e6), Eigen::VectorXd::Zero(12));
  EXPECT_TRUE(result.converged);
  EXPECT_LE((result.x - expected).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_EQ(result.atLower + result.atUpper, 0);
}

// Random problems with rows like the tone map's: pairs with a ratio, plus a diagonal that makes
// it strictly convex. Both stages are checked: the active-set stage alone, and projected Newton
// taking over after one active-set step (what happens on a cycle).
class RandomProblems : public ::testing::TestWithParam<int> {};

TEST_P(RandomProblems, MatchTheDenseOracle) {
  const int maxActiveSetIterations = GetParam();
  std::mt19937 random(11);
  std::normal_distribution<double> normal;
  std::uniform_int_distribution<int> column(0, 39);
  int boundsInPlay = 0, projectedNewtonUsed = 0;
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<double> target;
    int row = 0;
    for (int k = 0; k < 80; ++k, ++row) {
      const int i = column(random), j = column(random);
      if (i == j) continue;
      entries.emplace_back(row, i, 3.0);
      entries.emplace_back(row, j, -3.0 * std::exp(normal(random)));
      target.push_back(0);
    }
    for (int i = 0; i < 40; ++i, ++row) {
      entries.emplace_back(row, i, 0.1);
      target.push_back(0.1 * (0.5 + 0.6 * normal(random)));
    }
    target.resize(row, 0.0);
    SparseRows a(row, 40);
    a.setFromTriplets(entries.begin(), entries.end());
    const Eigen::VectorXd b = Eigen::Map<Eigen::VectorXd>(target.data(), row);
    const Eigen::VectorXd lower = Eigen::VectorXd::Constant(40, 0.05);
    const Eigen::VectorXd upper = Eigen::VectorXd::Constant(40, 1.0);
    const auto sparse = solveBoundedLeastSquares(a, b, lower, upper, Eigen::VectorXd::Zero(40), 200,
                                                 maxActiveSetIterations);
    const Eigen::VectorXd dense =
        testing::denseBoundedLeastSquares(Eigen::MatrixXd(a), b, lower, upper);
    ASSERT_TRUE(sparse.converged) << "trial " << trial;
    EXPECT_LE((sparse.x - dense).cwiseAbs().maxCoeff(), 1e-6) << "trial " << trial;
    boundsInPlay += sparse.atLower + sparse.atUpper > 0;
    projectedNewtonUsed += sparse.projectedNewtonIterations > 0;
  }
  EXPECT_GE(boundsInPlay, 10);  // the comparison covers active bounds, not only free solutions
  if (maxActiveSetIterations == 1) {
    EXPECT_GE(projectedNewtonUsed, 10);
  }
}

INSTANTIATE_TEST_SUITE_P(BoundedLeastSquares, RandomProblems, ::testing::Values(200, 1),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return info.param == 1 ? std::string("ProjectedNewtonStage")
                                                  : std::string("ActiveSetStage");
                         });

// The tone map's own rows on a small room (slanted edges, a window 1e4 above the walls).
TEST(BoundedLeastSquares, ToneMapMeshesMatchTheDenseOracle) {
  for (int lattice : {3, 5}) {
    const testing::HdrScene scene = testing::roomView(36, 24, 2, 7);
    const DisplaySpaces spaces = displaySpaces(scene.hdr, 0.05);
    const RegionMap regions = findRegions(scene.faces);
    const VertexMesh mesh = buildVertexMesh(regions, lattice);
    const ConstraintSystem system =
        buildConstraintSystem(mesh, regions, logScene(spaces, regions), ConstraintWeights{});
    ASSERT_LE(mesh.vertices.size(), 400u);
    ASSERT_GT(system.threeVariableRows, 0);
    const auto sparse = solveBoundedLeastSquares(system.matrix, system.target, system.lower,
                                                 system.upper, system.start);
    const Eigen::VectorXd dense = testing::denseBoundedLeastSquares(
        Eigen::MatrixXd(system.matrix), system.target, system.lower, system.upper);
    ASSERT_TRUE(sparse.converged);
    EXPECT_GT(sparse.atLower + sparse.atUpper, 0);
    EXPECT_LE((sparse.x - dense).cwiseAbs().maxCoeff(), 1e-6) << "lattice " << lattice;
  }
}

}  // namespace
}  // namespace penumbra
