#pragma once
// Curved primitives as convex polyhedra (Conway & Cottingham, the isoluminance contour model):
// a sphere and the generalised truncus (cylinders, cones, frusta, discs), tessellated so that
// their facets follow the laminae of the paper: the tessellation is symmetric about the
// direction of the light, with vertices at a cosine distribution along it.
//
// Sphere: rings of latitude about the light direction ("north" = towards the light) at polar
// angles iπ/N, each a regular 2N-gon, the poles on the light axis.
// Truncus (paper, appendix): ends E1 (radius r1) at centre + axis/2 and E2 (r2) at
// centre − axis/2; rim vertices at angles 2πj/N from L_E, the light direction projected onto the
// end planes, so their positions along L_E follow cos(2πj/N).
// FacetPlacement::Turned rotates the same facets by half a step (a facet, not a vertex or ring,
// faces the light): the placement the tessellation is measured against (docs/primitives.md).
#include "geometry/convex_polyhedron.hpp"

namespace penumbra {

struct SphereShape {
  Vec3 center = Vec3::Zero();
  double radius = 1.0;
};

struct TruncusShape {
  Vec3 center = Vec3::Zero();  // the middle of the axis
  Vec3 axis = Vec3::UnitZ();   // from end E2 to end E1; its length is the height
  double r1 = 1.0, r2 = 1.0;   // radii of E1 and E2; one may be 0 (a cone)
};

enum class FacetPlacement { Laminae, Turned };

// `facets`: N, the number of latitude bands of a sphere (2N segments around) or of side facets
// around a truncus. `light`: unit direction towards the strongest source. Vertices lie on the
// smooth surface (the polyhedron is inscribed).
ConvexPolyhedron tessellate(const SphereShape& sphere, int facets, const Vec3& light,
                            FacetPlacement placement, double tolerance);
ConvexPolyhedron tessellate(const TruncusShape& truncus, int facets, const Vec3& light,
                            FacetPlacement placement, double tolerance);

// Two unit vectors completing `axis` (unit) to a right-handed frame; the first is `preferred`
// projected off the axis when that is not (nearly) zero.
std::pair<Vec3, Vec3> frameAround(const Vec3& axis, const Vec3& preferred);

}  // namespace penumbra
