#pragma once
// The part of a solid's face that no other solid covers, as convex pieces: a floor under a wall
// or a desk top under a monitor is never seen, and a drawing of the face must leave it out.
#include <vector>

#include "geometry/convex_polyhedron.hpp"

namespace penumbra {

// `face` minus every solid in `others` (their closed insides, within `tolerance`), split into
// convex polygons: against each solid, the piece outside its first plane, then the piece inside
// that one and outside the second, and so on; what is inside every plane is dropped. Pieces
// no wider than 4 × `tolerance` are dropped: where two solids meet, the cuts along their
// common plane (each grown by `tolerance`) leave a strip twice the tolerance wide.
std::vector<ConvexPolygon> faceOutsideSolids(const ConvexPolygon& face,
                                             const std::vector<const ConvexPolyhedron*>& others,
                                             double tolerance);

}  // namespace penumbra
