#pragma once
// From the solved vertex values to every pixel (issue 5, "Pixels"): a pixel's display V is its own
// Space-3 V times the gain V / V₃ interpolated from the vertices of its own region, then held to
// [LowerBound, 1]. The interpolation is the bilinear tent of one lattice spacing, normalised over
// the vertices of the pixel's region that lie under it, so on the interior lattice it is bilinear
// interpolation and near an edge it uses only the pixel's side: never a vertex across an edge.
// A vertex pixel shows its solved value exactly. A pixel with no vertex of its region under the
// tent (a sliver thinner than the lattice) takes the mean gain of its region; a pixel on no
// surface keeps its Space-3 V.
#include <Eigen/Core>

#include "image/images.hpp"
#include "tonemap/display_spaces.hpp"
#include "tonemap/region_map.hpp"
#include "tonemap/vertex_mesh.hpp"

namespace penumbra {

ScalarImage interpolateDisplayValues(const VertexMesh& mesh, const RegionMap& regions,
                                     const DisplaySpaces& spaces, const Eigen::VectorXd& values);

}  // namespace penumbra
