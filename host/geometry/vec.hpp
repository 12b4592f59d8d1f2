#pragma once
// Host geometry is double precision (DESIGN.md): Eigen's fixed-size vectors.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace penumbra {
using Vec3 = Eigen::Vector3d;
}  // namespace penumbra
