#pragma once
// Host geometry is double precision; kernels get floats made from it. Eigen's fixed-size vectors.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace penumbra {
using Vec3 = Eigen::Vector3d;
}  // namespace penumbra
