#pragma once
// The test oracle for the tone map's solver: min ||A x - b||² subject to lower <= x <= upper on a
// small dense A, by a different algorithm on different linear algebra: the primal active-set
// method (Nocedal & Wright, Numerical Optimization, alg. 16.3) with each subproblem solved by a
// column-pivoted Householder QR of A itself (never the normal equations). Starts with every
// variable on its lower bound; releases one bound or stops at one blocking bound per step, so it
// takes many steps, which is fine for a few hundred variables.
#include <Eigen/Dense>
#include <stdexcept>
#include <vector>

namespace penumbra::testing {

inline Eigen::VectorXd denseBoundedLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                                                const Eigen::VectorXd& lower,
                                                const Eigen::VectorXd& upper) {
  const Eigen::Index n = a.cols();
  Eigen::VectorXd x = lower;
  std::vector<int> state(n, -1);  // -1 on lower, 0 free, +1 on upper
  const double scale = std::max(1.0, a.norm() * (b.norm() + a.norm()));
  for (int step = 0; step < 100 * static_cast<int>(n) + 100; ++step) {
    std::vector<Eigen::Index> freeIndex;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (state[i] == 0) freeIndex.push_back(i);
    }
    Eigen::VectorXd direction = Eigen::VectorXd::Zero(n);
    if (!freeIndex.empty()) {
      Eigen::MatrixXd af(a.rows(), static_cast<Eigen::Index>(freeIndex.size()));
      Eigen::VectorXd residual = b;
      for (Eigen::Index i = 0; i < n; ++i) {
        if (state[i] != 0) residual -= a.col(i) * x[i];
      }
      for (size_t k = 0; k < freeIndex.size(); ++k) af.col(k) = a.col(freeIndex[k]);
      const Eigen::VectorXd z = af.colPivHouseholderQr().solve(residual);
      for (size_t k = 0; k < freeIndex.size(); ++k) {
        direction[freeIndex[k]] = z[k] - x[freeIndex[k]];
      }
    }
    if (direction.norm() > 1e-13 * (1 + x.norm())) {
      double alpha = 1;
      Eigen::Index blocking = -1;
      int blockingSide = 0;
      for (Eigen::Index i : freeIndex) {
        if (direction[i] < 0 && (lower[i] - x[i]) / direction[i] < alpha) {
          alpha = (lower[i] - x[i]) / direction[i], blocking = i, blockingSide = -1;
        }
        if (direction[i] > 0 && (upper[i] - x[i]) / direction[i] < alpha) {
          alpha = (upper[i] - x[i]) / direction[i], blocking = i, blockingSide = 1;
        }
      }
      x += alpha * direction;
      if (blocking >= 0) {
        state[blocking] = blockingSide;
        x[blocking] = blockingSide < 0 ? lower[blocking] : upper[blocking];
      }
      continue;
    }
    // Stationary on the free variables: release the bound whose multiplier has the wrong sign.
    const Eigen::VectorXd gradient = a.transpose() * (a * x - b);
    Eigen::Index release = -1;
    double worst = 1e-12 * scale;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double wrong = state[i] < 0 ? -gradient[i] : state[i] > 0 ? gradient[i] : 0;
      if (wrong > worst) worst = wrong, release = i;
    }
    if (release < 0) return x;
    state[release] = 0;
  }
  throw std::runtime_error("dense bounded least squares did not converge");
}

}  // namespace penumbra::testing
