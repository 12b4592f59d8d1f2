#include "radiosity/radiosity_solver.hpp"

#include <numbers>
#include <stdexcept>

namespace penumbra {

RadiositySolution solveRadiosity(const Eigen::MatrixXd& transfer, const SurfaceMesh& mesh,
                                 const Eigen::MatrixX3d& direct) {
  const auto n = static_cast<Eigen::Index>(mesh.elements.size());
  if (transfer.rows() != n || transfer.cols() != n || direct.rows() != n) {
    throw std::invalid_argument("radiosity: transfer and direct illuminance do not fit the mesh");
  }
  RadiositySolution solution;
  solution.indirect.resize(n, 3);
  solution.luminance.resize(n, 3);
  Eigen::VectorXd factored;  // ρ/π of the channel whose factorisation is kept
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
  for (int c = 0; c < 3; ++c) {
    Eigen::VectorXd scale(n);  // ρ_c / π per element
    for (Eigen::Index i = 0; i < n; ++i)
      scale[i] = mesh.elements[static_cast<std::size_t>(i)].reflectance[c] / std::numbers::pi;
    const Eigen::MatrixXd reflect = transfer * scale.asDiagonal();
    const Eigen::VectorXd b = reflect * direct.col(c);
    if (factored.size() != n || factored != scale) {  // grey materials share one factorisation
      lu.compute(Eigen::MatrixXd::Identity(n, n) - reflect);
      factored = scale;
    }
    const Eigen::VectorXd x = n > 0 ? Eigen::VectorXd(lu.solve(b)) : Eigen::VectorXd(b);
    const double bNorm = b.norm();
    if (bNorm > 0.0) {
      const double r = (b - (x - reflect * x)).norm() / bNorm;
      solution.residual = std::max(solution.residual, r);
    }
    solution.indirect.col(c) = x;
    solution.luminance.col(c) = scale.cwiseProduct(direct.col(c) + x);
  }
  return solution;
}

}  // namespace penumbra
