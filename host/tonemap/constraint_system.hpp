#pragma once
// The constraint hierarchy as one weighted bounded least-squares problem (thesis eq. 5.8):
//   minimise ||A V - b||²  subject to  LowerBound <= V <= 1   (required, eq. 4.17)
// where each row of A is one constraint multiplied by its level's weight:
//   strong  across every visible edge, the Space-0 ratio (eq. 4.21, 4.22, 4.24)
//   medium  between neighbouring vertices of one region, their Space-0 ratio (eq. 4.34 when the
//           region is flat, where the ratio is 1)
//   weak    every vertex at its Space-3 value (eq. 4.35)
#include <Eigen/Sparse>
#include <cstdint>
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

ConstraintSystem buildConstraintSystem(const VertexMesh& mesh, const RegionMap& regions,
                                       const LogScene& scene, const ConstraintWeights& weights);

}  // namespace penumbra
