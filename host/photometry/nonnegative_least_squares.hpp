#pragma once
// Least squares with every unknown nonnegative: min |A x − b| subject to x >= 0, by Lawson and
// Hanson's active-set method ("Solving Least Squares Problems", 1974, ch. 23). The luminance fit
// (luminance_fit.hpp) takes it for sums of powers of cos φ with nonnegative coefficients, whose
// sum never cancels.
#include <Eigen/Dense>

namespace penumbra::photometry {

// The solution x >= 0. A's columns are scaled to unit length inside (they may differ by many
// orders of magnitude); columns of zero length get 0.
Eigen::VectorXd nonnegativeLeastSquares(const Eigen::MatrixXd& a, const Eigen::VectorXd& b);

}  // namespace penumbra::photometry
