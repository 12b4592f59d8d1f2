#include "tonemap/bounded_least_squares.hpp"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

namespace penumbra {
namespace {

// Q_FF y_F = r_F - Q_FA v_A with y_A = v_A, for a changing set F of free variables, through a
// matrix with Q's pattern whose fixed rows and columns are diag(Q) on the diagonal and 0 off it.
class ReducedSolver {
 public:
  explicit ReducedSolver(const Eigen::SparseMatrix<double>& q)
      : lowerQ_(q.triangularView<Eigen::Lower>()), reduced_(lowerQ_) {
    ldlt_.analyzePattern(reduced_);
  }

  Eigen::VectorXd solve(const std::vector<bool>& isFree, const Eigen::VectorXd& r,
                        const Eigen::VectorXd& fixedValue) {
    Eigen::VectorXd rhs = r;
    const Eigen::Index n = r.size();
    for (Eigen::Index column = 0; column < n; ++column) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(lowerQ_, column), out(reduced_, column);
           it; ++it, ++out) {
        const Eigen::Index row = it.row();
        if (row == column) {
          out.valueRef() = it.value();
          if (!isFree[row]) rhs[row] = it.value() * fixedValue[row];
          continue;
        }
        const bool rowFree = isFree[row], columnFree = isFree[column];
        out.valueRef() = (rowFree && columnFree) ? it.value() : 0.0;
        // Q is symmetric: the stored entry (row, column) also stands for (column, row).
        if (rowFree && !columnFree) rhs[row] -= it.value() * fixedValue[column];
        if (!rowFree && columnFree) rhs[column] -= it.value() * fixedValue[row];
      }
    }
    ldlt_.factorize(reduced_);
    if (ldlt_.info() != Eigen::Success) {
      throw std::runtime_error("bounded least squares: the factorisation failed");
    }
    return ldlt_.solve(rhs);
  }

 private:
  Eigen::SparseMatrix<double> lowerQ_, reduced_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt_;
};

struct Problem {
  const Eigen::SparseMatrix<double>& q;
  const Eigen::VectorXd& c;  // Aᵀb
  const Eigen::VectorXd& diagonal;
  const Eigen::VectorXd& lower;
  const Eigen::VectorXd& upper;

  Eigen::VectorXd project(const Eigen::VectorXd& x) const {
    return x.cwiseMax(lower).cwiseMin(upper);
  }
  double objective(const Eigen::VectorXd& x) const { return 0.5 * x.dot(q * x) - c.dot(x); }
  // The KKT residual of a feasible x: how far a diagonally scaled gradient step moves it, after
  // projection. 0 exactly at the solution.
  double stationarity(const Eigen::VectorXd& x, const Eigen::VectorXd& gradient) const {
    return (x - project(x - gradient.cwiseQuotient(diagonal))).cwiseAbs().maxCoeff();
  }
};

// x in log V for the tone map (1e-10 is a relative change of display V of 1e-10): far below
// what 8 bits can show.
constexpr double kStationarity = 1e-10;

// Stage 1. Returns true when x, put on its bounds, satisfies the KKT conditions; false on a
// cycle or at the iteration limit, with x the last iterate. The KKT test, not "the active set
// repeated", ends it: a variable on its bound with a zero multiplier is free and active at once,
// and rounding flips such degenerate variables back and forth (a thousand of them at 1920x1080)
// long after the solution is found.
bool primalDualActiveSet(const Problem& p, ReducedSolver& solver, Eigen::VectorXd& x,
                         int maxIterations, int& iterations) {
  const Eigen::Index n = x.size();
  std::vector<signed char> state(n, 0), previous;
  std::unordered_set<std::string> seen;
  Eigen::VectorXd lambda = p.q * x - p.c;
  std::vector<bool> isFree(n);
  for (iterations = 0; iterations < maxIterations;) {
    for (Eigen::Index i = 0; i < n; ++i) {
      // The scale 1/Q_ii makes the prediction independent of the rows' weights.
      const double trial = x[i] - lambda[i] / p.diagonal[i];
      state[i] = trial < p.lower[i] ? -1 : trial > p.upper[i] ? 1 : 0;
    }
    if (state == previous) return true;
    if (!seen.insert(std::string(state.begin(), state.end())).second) return false;  // a cycle
    previous = state;
    ++iterations;
    Eigen::VectorXd bound(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      isFree[i] = state[i] == 0;
      bound[i] = state[i] < 0 ? p.lower[i] : p.upper[i];
    }
    x = solver.solve(isFree, p.c, bound);
    const Eigen::VectorXd feasible = p.project(x);
    if (p.stationarity(feasible, p.q * feasible - p.c) <= kStationarity) {
      x = feasible;
      return true;
    }
    lambda = p.q * x - p.c;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (isFree[i]) lambda[i] = 0;
    }
  }
  return false;
}

// Stage 2: Bertsekas's projected Newton with the ε-active set and an Armijo search along the
// projection arc; Newton on the free variables, diagonally scaled gradient on the ε-active ones.
bool projectedNewton(const Problem& p, ReducedSolver& solver, Eigen::VectorXd& x, int maxIterations,
                     int& iterations) {
  const Eigen::Index n = x.size();
  constexpr double kSufficientDecrease = 1e-4;
  x = p.project(x);
  std::vector<bool> isFree(n);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  for (iterations = 0; iterations < maxIterations; ++iterations) {
    const Eigen::VectorXd gradient = p.q * x - p.c;
    const Eigen::VectorXd scaled = gradient.cwiseQuotient(p.diagonal);
    const double stationarity = p.stationarity(x, gradient);
    if (stationarity <= kStationarity) return true;
    const double epsilon = std::min(1e-3, stationarity);
    for (Eigen::Index i = 0; i < n; ++i) {
      isFree[i] = !((x[i] <= p.lower[i] + epsilon && gradient[i] > 0) ||
                    (x[i] >= p.upper[i] - epsilon && gradient[i] < 0));
    }
    Eigen::VectorXd direction = solver.solve(isFree, -gradient, zero);
    for (Eigen::Index i = 0; i < n; ++i) {
      if (!isFree[i]) direction[i] = -scaled[i];
    }
    const double f0 = p.objective(x);
    double alpha = 1;
    Eigen::VectorXd next;
    for (int halving = 0; halving < 40; ++halving, alpha *= 0.5) {
      next = p.project(x + alpha * direction);
      double decrease = 0;
      for (Eigen::Index i = 0; i < n; ++i) {
        decrease +=
            isFree[i] ? -alpha * gradient[i] * direction[i] : gradient[i] * (x[i] - next[i]);
      }
      if (f0 - p.objective(next) >= kSufficientDecrease * decrease) break;
    }
    x = next;
  }
  return false;
}

}  // namespace

BoundedLeastSquaresResult solveBoundedLeastSquares(
    const Eigen::SparseMatrix<double, Eigen::RowMajor>& a, const Eigen::VectorXd& b,
    const Eigen::VectorXd& lower, const Eigen::VectorXd& upper, const Eigen::VectorXd& start,
    int maxIterations, int maxActiveSetIterations) {
  BoundedLeastSquaresResult result;
  result.x = start.cwiseMax(lower).cwiseMin(upper);
  if (a.cols() == 0) {
    result.converged = true;
    return result;
  }
  const Eigen::SparseMatrix<double> at = a.transpose();
  const Eigen::SparseMatrix<double> q = (at * a).pruned();
  const Eigen::VectorXd c = at * b;
  const Eigen::VectorXd diagonal = q.diagonal();
  if ((diagonal.array() <= 0).any()) {
    throw std::invalid_argument("bounded least squares: a variable appears in no row");
  }
  const Problem problem{q, c, diagonal, lower, upper};
  ReducedSolver solver(q);
  result.converged = primalDualActiveSet(problem, solver, result.x,
                                         std::min(maxIterations, maxActiveSetIterations),
                                         result.activeSetIterations);
  if (!result.converged) {
    result.converged =
        projectedNewton(problem, solver, result.x, maxIterations - result.activeSetIterations,
                        result.projectedNewtonIterations);
  }
  // The bounds are required: what rounding leaves outside them is put back on them.
  result.x = problem.project(result.x);
  for (Eigen::Index i = 0; i < result.x.size(); ++i) {
    result.atLower += result.x[i] == lower[i];
    result.atUpper += result.x[i] == upper[i];
  }
  return result;
}

}  // namespace penumbra
