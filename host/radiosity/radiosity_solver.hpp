#pragma once
// The radiosity equations on the elements, per RGB channel c:
//   E_ind = T · diag(ρ_c / π) · (E_dir + E_ind),
// E the element-average illuminance, ρ the element's diffuse reflectance, L = ρ·E/π the
// luminance each element then sends out. Solved per channel by BiCGSTAB on products with T (the
// system I - T·diag(ρ_c/π) is never formed) to a relative residual of 1e-12
// (radiosity_solver.cpp says why not a factorisation), the residual measured after it.
#include <Eigen/Dense>

#include "radiosity/surface_mesh.hpp"

namespace penumbra {

struct RadiositySolution {
  Eigen::MatrixX3d indirect;   // lx, element-average interreflected illuminance per channel
  Eigen::MatrixX3d luminance;  // cd/m², the luminance each element reflects, per channel
  double residual = 0.0;       // max over channels of |b - A·x| / |b| (0 when b = 0)
};

// `transfer` from elementTransfer, `direct` the element-average direct illuminance per channel
// (lx, one row per element).
RadiositySolution solveRadiosity(const Eigen::MatrixXd& transfer, const SurfaceMesh& mesh,
                                 const Eigen::MatrixX3d& direct);

// The Rec. 709 luminance weights: a channel triple's photometric value (lx from lx per channel).
inline double photometric(const Eigen::Vector3d& rgb) {
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

}  // namespace penumbra
