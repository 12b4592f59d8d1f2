#pragma once
// The independent reference: dense deterministic sampling of each source face
// (about n² equal cells of a centred Fibonacci lattice, each sampled at its midpoint; the .cpp
// says why not an n × n grid of cells) with exact segment-versus-convex-polyhedron tests, in
// double precision on the host. Shares no code with the kernel path.
#include <span>
#include <vector>

#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// E in lx at every point, summed over all sources and luminaires (luminaire_illuminance.hpp).
std::vector<double> referenceIlluminance(const Scene& scene, std::span<const SamplePoint> points,
                                         int n);

}  // namespace penumbra
