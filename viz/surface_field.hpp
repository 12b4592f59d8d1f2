#pragma once
// The room's surfaces with their light, as written to surfaces.vtp: the sample points with
// "E_lx" (illuminance, lx), "L_cd_m2" (luminance of a diffuse surface, L = ρ·E/π, cd/m²; NaN on
// solids without a material) and "Normals"; one polygon cell per lattice cell with "solid" and
// "face" indices; the solids' names in the field array "solid_names".
#include <span>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "scene/scene.hpp"
#include "viz/surface_sampling.hpp"

namespace penumbra::viz {

// The luminance factor of a solid's material: ρ as luminance Y (Rec.709 weights of its RGB
// reflectance); NaN when the solid has no material.
double reflectanceY(const Scene& scene, int solid);

// `illuminance` holds E in lx for each of mesh.points.
vtkSmartPointer<vtkPolyData> surfacePolyData(const Scene& scene, const SurfaceMesh& mesh,
                                             std::span<const double> illuminance);

}  // namespace penumbra::viz
