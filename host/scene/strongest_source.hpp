#pragma once
// Which way the light mainly comes from at a point: what curved primitives orient their facets
// by (Conway & Cottingham: the tessellation is symmetric about the light source vector).
#include <vector>

#include "scene/scene.hpp"

namespace penumbra {

// The unit direction from `point` towards the source that lights it most, judged by each
// emitting face as a point source at its centroid, L·A·cos(θ_source)/d² (good enough to choose
// a direction; the illuminance itself is always exact). +z when no source faces the point.
Vec3 towardsStrongestSource(const std::vector<Source>& sources, const Vec3& point);

}  // namespace penumbra
