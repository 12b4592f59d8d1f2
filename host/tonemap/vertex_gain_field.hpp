#pragma once
// From the solved vertex values (x = log V) to every pixel (docs/tonemap.md, "Pixels"): a
// pixel's display V is its own Space-0 V times a gain, log G = x − log V₀ interpolated from the
// vertices of its own region, held to [LowerBound, 1]. Never a vertex across an edge: only
// vertices of the pixel's region contribute.
//
// The interpolation is joint bilateral upsampling (Kopf et al. 2007): the bilinear tent of one
// lattice spacing times a Gaussian in log(V₀ pixel / V₀ vertex), normalised. On a smooth region it
// is bilinear interpolation of the log gain; across a shadow edge inside a face (an umbra beside a
// lit part, where the ratio is large or infinite) each side takes the gains of its own side.
//
// Why V₀: a gain on V₀ keeps Space-0 ratios between vertices (detail finer than the lattice, a
// shadow edge between two lattice columns) where a gain on a curve of V₀ (the linear V₃ or the
// exposure curve) would flatten them.
//
// A vertex pixel shows its solved value exactly. A pixel whose V₀ is unlike that of every vertex
// under its tent takes the gain of the most alike; a pixel with no vertex of its region under its
// tent (a sliver thinner than the lattice) takes its region's mean log V; a pixel on no surface
// shows the exposure curve (Space 3).
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
