#pragma once
// What the placement checks of sources and grids share: the room's interior, half-space tests
// with the input tolerance, the solid that holds a shape, and extents in words.
#include <optional>
#include <string>
#include <vector>

#include "geometry/bounding_box.hpp"
#include "geometry/plane.hpp"
#include "scene/scene.hpp"

namespace penumbra::scenefile {

// The room's interior [0, X] × [0, Y] × [0, Z]; empty without a room.
BoundingBox roomInterior(const std::optional<Room>& room);
// p lies in the closed box grown by `tolerance`.
bool insideBox(const BoundingBox& box, const Vec3& p, double tolerance);
// Some point lies more than `tolerance` in front of the plane (on the side its normal points to).
bool anyInFront(const Plane& plane, const std::vector<Vec3>& points, double tolerance);
// The index of a solid that holds the convex hull of `points` wholly: every point inside it or on
// its boundary, and their mean strictly inside (a shape lying on a face is not held); -1 if none.
int solidHolding(const std::vector<Solid>& solids, const std::vector<Vec3>& points,
                 double tolerance);
// "x 1 to 2 m, y 0.5 m, z 2.95 m": the extent of the points along each axis.
std::string describeExtent(const std::vector<Vec3>& points);
// "[0, 0, -1]": a unit direction to four decimals.
std::string describeDirection(const Vec3& direction);

}  // namespace penumbra::scenefile
