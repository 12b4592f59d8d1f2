#pragma once
// What a plan shows besides the cut: the room's openings and the luminaires, projected onto the
// picture (a window in its wall, a ceiling panel over the work plane), in plot coordinates.
#include <vector>

#include <Eigen/Core>

#include "scene/scene.hpp"
#include "viz/planar_field.hpp"

namespace penumbra::viz {

using PlotPolygon = std::vector<Eigen::Vector2d>;  // plot coordinates, m

// Each opening as the outline of its hole through the wall (inner and outer rectangles together).
std::vector<PlotPolygon> projectedOpenings(const Scene& scene, const PlotPlane& plot);

// Each face of each source that is not an opening, as it projects; faces seen edge-on (a
// window's glazing in a plan) are left out.
std::vector<PlotPolygon> projectedLuminaires(const Scene& scene, const PlotPlane& plot);

}  // namespace penumbra::viz
