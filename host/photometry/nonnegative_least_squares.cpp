#include "photometry/nonnegative_least_squares.hpp"

#include <algorithm>
#include <vector>

namespace penumbra::photometry {
namespace {

// The unconstrained least-squares solution on the columns in `active`, 0 elsewhere.
Eigen::VectorXd activeSetSolution(const Eigen::MatrixXd& a, const Eigen::VectorXd& b,
                                  const std::vector<bool>& active) {
  std::vector<Eigen::Index> columns;
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    if (active[static_cast<std::size_t>(j)]) columns.push_back(j);
  Eigen::MatrixXd sub(a.rows(), static_cast<Eigen::Index>(columns.size()));
  for (std::size_t i = 0; i < columns.size(); ++i)
    sub.col(static_cast<Eigen::Index>(i)) = a.col(columns[i]);
  const Eigen::VectorXd s = sub.colPivHouseholderQr().solve(b);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(a.cols());
  for (std::size_t i = 0; i < columns.size(); ++i) x(columns[i]) = s(static_cast<Eigen::Index>(i));
  return x;
}

}  // namespace

Eigen::VectorXd nonnegativeLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  const Eigen::Index n = a.cols();
  Eigen::VectorXd scale = a.colwise().norm().transpose();
  Eigen::MatrixXd scaled = a;
  for (Eigen::Index j = 0; j < n; ++j)
    if (scale(j) > 0.0) scaled.col(j) /= scale(j);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  std::vector<bool> active(static_cast<std::size_t>(n), false);
  // The gradient's threshold: a column whose correlation with the residual is below rounding of
  // |b| does not enter.
  const double threshold = 1e-12 * std::max(b.norm(), 1e-300);
  // Each outer step adds a column; the inner steps only remove: Lawson and Hanson bound the
  // whole by a finite number of steps, 3n outer steps are a generous guard.
  for (Eigen::Index outer = 0; outer < 3 * n; ++outer) {
    const Eigen::VectorXd gradient = scaled.transpose() * (b - scaled * x);
    Eigen::Index entering = -1;
    double largest = threshold;
    for (Eigen::Index j = 0; j < n; ++j)
      if (!active[static_cast<std::size_t>(j)] && scale(j) > 0.0 && gradient(j) > largest) {
        largest = gradient(j);
        entering = j;
      }
    if (entering < 0) break;
    active[static_cast<std::size_t>(entering)] = true;
    for (;;) {
      const Eigen::VectorXd s = activeSetSolution(scaled, b, active);
      double alpha = 1.0;
      Eigen::Index leaving = -1;
      for (Eigen::Index j = 0; j < n; ++j)
        if (active[static_cast<std::size_t>(j)] && s(j) <= 0.0) {
          const double gap = x(j) - s(j);  // >= 0: x(j) >= 0 >= s(j)
          const double step = gap > 0.0 ? x(j) / gap : 0.0;
          if (leaving < 0 || step < alpha) {
            alpha = step;
            leaving = j;
          }
        }
      if (leaving < 0) {
        x = s;
        break;
      }
      // Step towards s until the first coefficient reaches 0, and let it go.
      x += alpha * (s - x);
      x(leaving) = 0.0;
      for (Eigen::Index j = 0; j < n; ++j)
        if (active[static_cast<std::size_t>(j)] && x(j) <= 0.0) {
          active[static_cast<std::size_t>(j)] = false;
          x(j) = 0.0;
        }
    }
  }
  for (Eigen::Index j = 0; j < n; ++j) x(j) = scale(j) > 0.0 ? x(j) / scale(j) : 0.0;
  return x;
}

}  // namespace penumbra::photometry
