#pragma once
// Builds and validates convex geometry from shape specs: the polyhedra of solids and polyhedron
// sources (box, prism, hull) and the polygons typed by hand (source polygons, prism bases).
#include <string_view>
#include <vector>

#include "geometry/convex_polyhedron.hpp"
#include "scene/build_context.hpp"
#include "scene/scene_spec.hpp"

namespace penumbra::scenefile {

// A convex, planar polygon with area, vertices as given; otherwise a SceneError at `where`.
ConvexPolygon validatedPolygon(const std::vector<Vec3>& vertices, const Where& where,
                               const BuildContext& context);

// The polyhedron of a box, prism or hull spec (anything else is a programming error).
ConvexPolyhedron buildPolyhedron(const ShapeSpec& shape, const Where& where,
                                 const BuildContext& context);

bool isPolyhedron(const ShapeSpec& shape);

}  // namespace penumbra::scenefile
