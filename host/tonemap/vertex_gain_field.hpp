#pragma once
// From the solved vertex values to every pixel (docs/tonemap.md, "Pixels"): a pixel's display V
// is its own Space-0 V times a gain G = V / V₀ interpolated from the vertices of its own region,
// held to [LowerBound, 1]. Never a vertex across an edge: only vertices of the pixel's region
// contribute.
//
// The interpolation is joint bilateral upsampling (Kopf et al. 2007): the bilinear tent of one
// lattice spacing times a Gaussian in log(V₀ pixel / V₀ vertex), normalised. On a smooth region it
// is bilinear interpolation of the gain; across a shadow edge inside a face (an umbra beside a lit
// part, where the ratio is large or infinite) each side takes the gains of its own side.
//
// Why V₀ and not V₃: V₃ = LowerBound + (1 - LowerBound) V₁ is affine,
// V₃ ∝ V₀ + LowerBound·MaxRGB/(1 - LowerBound). With a window in view that offset is larger than
// every room surface, so a gain applied to V₃ flattens every gradient between two vertices and
// the ratio at every edge pixel that is not a vertex (measured in docs/tonemap.md). A gain on V₀
// keeps Space-0 ratios between vertices exactly where the solve keeps them at the vertices.
//
// A vertex pixel shows its solved value exactly. A pixel whose V₀ is unlike that of every vertex
// under its tent takes the gain of the most alike; a pixel with no vertex of its region under its
// tent (a sliver thinner than the lattice) takes its region's mean V; a pixel on no surface keeps
// its Space-3 V.
#include <Eigen/Core>

#include "image/images.hpp"
#include "tonemap/display_spaces.hpp"
#include "tonemap/log_scene.hpp"
#include "tonemap/region_map.hpp"
#include "tonemap/vertex_mesh.hpp"

namespace penumbra {

ScalarImage interpolateDisplayValues(const VertexMesh& mesh, const RegionMap& regions,
                                     const DisplaySpaces& spaces, const LogScene& scene,
                                     const Eigen::VectorXd& values);

}  // namespace penumbra
