#pragma once
// min ||A x - b||²  subject to  lower <= x <= upper, for large sparse A (thesis eq. 5.8).
//
// The normal matrix Q = AᵀA of the tone map is a weighted graph Laplacian plus a diagonal (the
// weak rows), so the problem is a strictly convex box-constrained QP, solved in two stages:
//  1. the primal-dual active-set method (Hintermüller, Ito & Kunisch 2002): guess which
//     variables sit on a bound from x - λ/diag(Q), fix them, solve the rest exactly with one
//     sparse LDLᵀ factorisation, update λ = Qx - Aᵀb, repeat until x satisfies the KKT conditions.
//     Few steps when it converges, but it is only guaranteed to for M-matrices, and the
//     three-variable edge rows (eq. 4.22/4.24) put positive entries off Q's diagonal: on the
//     staircase it cycles;
//  2. so when a guess comes back (a cycle), or after maxActiveSetIterations, projected Newton
//  (Bertsekas 1982) takes over from
//     where it stopped: the same reduced LDLᵀ solve as the step, an Armijo search along the
//     projection arc, which decreases the objective every step and so cannot cycle.
// The pattern of every reduced system is Q's own (fixed variables become scaled identity rows),
// so the fill-reducing ordering and symbolic analysis are done once.
// Why this and not CHOLMOD, L-BFGS-B or projected gradient: see bench/tonemap_bench.cpp and
// docs/tonemap.md (measured).
#include <Eigen/Sparse>

namespace penumbra {

struct BoundedLeastSquaresResult {
  Eigen::VectorXd x;                  // within [lower, upper] exactly
  int activeSetIterations = 0;        // stage 1
  int projectedNewtonIterations = 0;  // stage 2 (0 when stage 1 converged)
  // The KKT conditions hold: a diagonally scaled projected-gradient step moves x by at most
  // 1e-10 (in the unknowns' units: log V for the tone map).
  bool converged = false;
  int atLower = 0, atUpper = 0;
  int outerIterations() const { return activeSetIterations + projectedNewtonIterations; }
};

BoundedLeastSquaresResult solveBoundedLeastSquares(
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
    const Eigen::VectorXd& lower, const Eigen::VectorXd& upper, const Eigen::VectorXd& start,
    int maxIterations = 200, int maxActiveSetIterations = 200);

}  // namespace penumbra
