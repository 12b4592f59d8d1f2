#pragma once
// A second independent reference: the exact direct illuminance in double precision, by a method
// other than the kernel's. The kernel clips each edge against side planes through P in 3-D; this
// projects each occluder from P onto the source face's plane (a convex shadow polygon there),
// takes the face (clipped by P's horizon) minus the union of those polygons in the plane's 2-D
// coordinates, and sums Lambert's contour terms over that region's boundary in double. Exact up
// to double rounding (closed forms to 1e-12; where edges coincide, pieces end within 2.5e-10 of
// the face's size of the true crossing), so it resolves the kernel's float error, which the
// sampled reference (n = 1024: about 1e-6) cannot.
//
// The scene semantics follow referenceIlluminance: the solid a point lies on never blocks it, and
// a solid touching the source plane from behind (a luminaire's housing, a ceiling slab around a
// flush panel) does not block it.
#include <span>
#include <vector>

#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// E in lx at every point: out[source][point] when perSource, else one row summed over sources.
std::vector<std::vector<double>> exactIlluminance(const Scene& scene,
                                                  std::span<const SamplePoint> points,
                                                  bool perSource = false);

}  // namespace penumbra
