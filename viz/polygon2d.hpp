#pragma once
// Convex polygons in a plane (face coordinates, plot coordinates, pixels): clipping, area, hull.
#include <vector>

#include <Eigen/Core>

namespace penumbra::viz {

using Polygon2 = std::vector<Eigen::Vector2d>;

// The part of convex `polygon` on the left of the directed line from → to (Sutherland-Hodgman).
Polygon2 clipLeftOf(const Polygon2& polygon, const Eigen::Vector2d& from,
                    const Eigen::Vector2d& to);

// The part of convex `polygon` inside the box [lo, hi]; empty when nothing is left.
Polygon2 clipToBox(const Polygon2& polygon, const Eigen::Vector2d& lo, const Eigen::Vector2d& hi);

// Signed area: positive for counter-clockwise.
double signedArea(const Polygon2& polygon);

// The convex hull, counter-clockwise, without collinear points (Andrew's monotone chain).
Polygon2 convexHull(Polygon2 points);

}  // namespace penumbra::viz
