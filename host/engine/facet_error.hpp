#pragma once
// How well a tessellated curved surface stands in for the smooth one as a receiver: E on the
// facets against E on the smooth surface at the same points, to measure whether more facets pay
// (docs/primitives.md).
// Points are taken on the smooth surface along directions from the primitive's centre; the
// facet point is where the same ray meets the polyhedron, with the facet's normal.
#include <vector>

#include "engine/illuminance_engine.hpp"
#include "geometry/convex_polyhedron.hpp"

namespace penumbra {

struct FacetError {
  double mean = 0.0, max = 0.0;  // relative to the smooth surface's E
  int points = 0;                // points compared (those the sources light)
};

// `onSmooth`: points on the smooth surface with its normals (unit), `centre` inside the solid.
// Points whose smooth E is below `floor` × the largest smooth E are left out: relative errors
// at the terminator, where E → 0, say nothing about the picture.
FacetError facetError(IlluminanceEngine& engine, const ConvexPolyhedron& facets, const Vec3& centre,
                      const std::vector<SamplePoint>& onSmooth, double floor = 0.01);

}  // namespace penumbra
