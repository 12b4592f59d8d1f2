#pragma once
// The constraint hierarchy as one weighted bounded least-squares problem (thesis eq. 5.8) on
// x = log V per vertex:
//   minimise ||A x - b||²  subject to  log LowerBound <= x <= 0   (required, eq. 4.17)
// where each row of A is one constraint multiplied by its level's weight (log_scene.hpp gives
// the targets):
//   strong  across every visible edge, the compressed Space-0 log ratio (eq. 4.21, 4.22, 4.24 in
//           logs)
//   medium  between neighbouring vertices of one region, their attenuated Space-0 log ratio (0
//           on a flat region, eq. 4.34)
//   weak    every vertex at the log of its Space-3 value, the exposure curve (eq. 4.35)
#include <Eigen/Sparse>
#include <cstdint>
#include <initializer_list>
#include <utility>
#include <vector>

#include "tonemap/log_scene.hpp"
#include "tonemap/region_map.hpp"
#include "tonemap/vertex_mesh.hpp"

namespace penumbra {

enum class ConstraintLevel : uint8_t { Strong, Medium, Weak };

struct ConstraintWeights {
  double strong = 10, medium = 100, weak = 0.1;
};

struct ConstraintSystem {
  Eigen::SparseMatrix<double, Eigen::RowMajor> matrix;  // A, rows already weighted
  Eigen::VectorXd target;                               // b, weighted
  Eigen::VectorXd lower, upper;                         // LowerBound and 1 per vertex
  Eigen::VectorXd start;                                // Space-3 V per vertex
  std::vector<ConstraintLevel> level;                   // per row
  std::vector<double> weight;                           // per row, to report unweighted residuals
  int threeVariableRows = 0;
};

// Rows as they are made: each one constraint times its level's weight.
struct ConstraintRows {
  std::vector<Eigen::Triplet<double>> entries;
  std::vector<double> target;
  std::vector<ConstraintLevel> level;
  std::vector<double> weight;

  void add(ConstraintLevel rowLevel, double rowWeight,
           std::initializer_list<std::pair<int, double>> terms, double rhs);
  // Moves the rows into `system` (A, b, levels, weights) with bounds [logLowerBound, 0] on each
  // of `variables` unknowns.
  void fill(ConstraintSystem& system, int variables, double logLowerBound);
};

// The image lattice's rows (vertex_mesh.hpp).
ConstraintSystem buildConstraintSystem(const VertexMesh& mesh, const RegionMap& regions,
                                       const LogScene& scene, const ConstraintWeights& weights);

}  // namespace penumbra
