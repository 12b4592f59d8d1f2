#pragma once
// What a plan or elevation shows of the scene: the cuts of its solids by the grid's plane (walls,
// a cabinet standing through the work plane) and the room's interior outline.
#include <string>
#include <vector>

#include "geometry/convex_polyhedron.hpp"
#include "scene/scene.hpp"

namespace penumbra::viz {

struct SolidSection {
  std::string name;
  bool roomSlab = false;      // one of the room's floor, ceiling and wall slabs
  std::vector<Vec3> polygon;  // convex, in order around it
};

// The convex polygon where `plane` cuts `solid`, or the face `solid` stands on when that face
// lies in the plane and the solid is on the plane's front side (the normal's side: where a grid
// looks). Empty otherwise: a desk whose top is a desk-top grid's plane is not drawn over it,
// a wall standing on a floor grid is.
std::vector<Vec3> sectionOf(const ConvexPolyhedron& solid, const Plane& plane, double tolerance);

// Every solid with a section, in scene order. `plane`'s normal is the grid's.
std::vector<SolidSection> solidSections(const Scene& scene, const Plane& plane);

// The outline of `solid` seen along the plane's normal, on the plane (the convex hull of its
// vertices projected onto it, counter-clockwise about the normal), when the whole solid lies in
// front of the plane farther than `tolerance`: a desk top or a shelf over a work plane. Empty
// otherwise (a solid the plane cuts has a section instead).
std::vector<Vec3> footprintOf(const ConvexPolyhedron& solid, const Plane& plane, double tolerance);

// Every solid other than the room's slabs with a footprint, in scene order.
std::vector<SolidSection> solidFootprints(const Scene& scene, const Plane& plane);

// The section of the room's interior box [0, X] × [0, Y] × [0, Z]; empty without a room or when
// the plane misses it.
std::vector<Vec3> roomOutline(const Scene& scene, const Plane& plane);

}  // namespace penumbra::viz
