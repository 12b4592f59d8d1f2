#pragma once
// The transfer between elements: how much illuminance each element's light gives each other
// element, by the kernel's exact occluded contour integral at the receiving element's
// quadrature nodes. It depends on the geometry only (not on reflectances or sources).
#include <Eigen/Dense>

#include "engine/illuminance_engine.hpp"
#include "radiosity/surface_mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// The scene's solids with every element as a Lambertian source of 1 cd/m² emitting from its
// face: what the kernel integrates over for the transfer and for the final gather. Sources,
// grids and views of `scene` are left out.
Scene elementScene(const Scene& scene, const SurfaceMesh& mesh);

// t(i, j): the mean over element i's nodes (by their weights) of the illuminance in lx that
// element j gives at 1 cd/m². `engine` must hold elementScene(scene, mesh) with unit
// luminances. Within the quadrature's error, area(i)·t(i, j) = area(j)·t(j, i) (reciprocity),
// and in a closed room every row sums to π (each node sees a whole hemisphere of elements).
Eigen::MatrixXd elementTransfer(IlluminanceEngine& engine, const SurfaceMesh& mesh);

}  // namespace penumbra
