#pragma once
// Light that depends on the direction only (a source at infinity: the sun, the sky), integrated
// exactly in double on the host. A polygon placed per receiving point P beyond every solid has,
// seen from P, exactly the directions of the part of the source it stands for, and every solid
// lies between it and P: E is then Lambert's contour integral (or the cosine moments of a
// luminance polynomial) over the part of that polygon P sees past the solids
// (reference/visible_boundary.hpp), exact to rounding whatever the solids are, inside the room
// or outside it.
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// Where a far polygon may stand for a point: beyond the box of every solid's vertices.
struct FarPlacement {
  Vec3 centre = Vec3::Zero();  // m: the centre of the solids' box (the origin without solids)
  double diagonal = 0.0;       // m: its diagonal (0 without solids)

  static FarPlacement of(const Scene& scene);
  // m: a distance from `point` at which every solid vertex is nearer than half of it, so that a
  // polygon whose every point is at least that far lies beyond every solid.
  double distance(const Vec3& point) const;
};

// The part of `far` (seen from p) whose directions pass through the convex polygon `hole`: `far`
// cut by the plane through p and each edge of the hole. Empty when p lies in the hole's plane.
ConvexPolygon throughHole(const ConvexPolygon& far, const Vec3& p, const ConvexPolygon& hole);

// The polygon that `hole` (a convex polygon whose normal faces p, p strictly in front of it)
// covers seen from p, moved along its directions to the plane parallel to it at `distance` (m)
// from p: the homothety of ratio distance / (p's height over the hole's plane) about p. It keeps
// the hole's orientation (its normal faces p).
ConvexPolygon farImage(const ConvexPolygon& hole, const Vec3& p, double distance);

// The moments M_0..M_order = ∫ (axis·ω)^k (n·ω) dω over the part of `polygon` (emitting towards
// the point) that `point` sees past the solids of `scene` (reference/cosine_moments.hpp; n the
// point's unit normal); zeros when it sees none. Every direction of the polygon must have
// axis·ω > −1.
std::vector<double> visibleMoments(const ConvexPolygon& polygon, const SamplePoint& point,
                                   const Scene& scene, double tolerance, const Vec3& axis,
                                   int order);

// M_0 alone: the projected solid angle (sr) of the part of `polygon` that `point` sees.
double visibleProjectedSolidAngle(const ConvexPolygon& polygon, const SamplePoint& point,
                                  const Scene& scene, double tolerance);

}  // namespace penumbra
