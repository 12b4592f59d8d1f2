#pragma once
// The sun's direct light averaged over each element of the interreflection mesh. The mesh does
// not follow the sun (so that a scene's daylight factor does not depend on it), so the edge of a
// sun patch crosses elements; there the element's own quadrature nodes, placed for smooth light,
// average a step. An element whose nodes do not all receive the same sunlight is averaged again
// by the midpoint rule on kSunCellsPerSide² cells, whose error falls like 1/kSunCellsPerSide of
// the part of the element the edge crosses.
#include <Eigen/Core>

#include "radiosity/host_light.hpp"
#include "radiosity/surface_mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

inline constexpr int kSunCellsPerSide = 32;

// lx per element; `sun` the sun's direct light at points (HostLight::sun), `nodeSun` its values at
// the mesh's nodes.
Eigen::VectorXd sunElementAverage(const Scene& scene, const HostDirectLight& sun,
                                  const SurfaceMesh& mesh, const Eigen::VectorXd& nodeSun,
                                  int cellsPerSide = kSunCellsPerSide);

}  // namespace penumbra
