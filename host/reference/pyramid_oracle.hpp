#pragma once
// The exact questions the shadow volumes answer, asked directly: the oracle the shadow-volume
// tests hold the volumes' planes against (tests/shadow_volume_test.cpp). Plain double-precision
// geometry, sharing no code with host/shadow: a separating-axis test between two convex sets and a
// clipped segment.
#include <span>

#include "geometry/convex_polyhedron.hpp"

namespace penumbra {

// Signed separation of two convex polyhedra along the best of the separating-axis candidates
// (face normals of both, cross products of their edges): > 0 when they are disjoint (a lower
// bound of the gap), <= 0 when they meet (minus the least overlap along those axes).
double separation(const ConvexPolyhedron& a, const ConvexPolyhedron& b);

// The same for the pyramid conv(apex, source), source being the vertices of a polygon or of a
// polyhedron: v blocks part of the source from apex iff this is < 0. +infinity when the
// pyramid is flat (apex in the plane of a polygon source: it sees nothing of it).
double pyramidSeparation(const Vec3& apex, std::span<const Vec3> source, const ConvexPolyhedron& v,
                         double tolerance);

// True when the segment from a to b misses v grown by `margin` on every face: a point at a sees
// the point b clearly past v.
bool segmentClears(const Vec3& a, const Vec3& b, const ConvexPolyhedron& v, double margin);

}  // namespace penumbra
