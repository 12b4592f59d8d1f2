#pragma once
// The boundary of the part of a planar source face that a point sees past the scene's solids, in
// double precision (the geometry of exact_illuminance.hpp, shared by every emission law that is
// integrated along that boundary: Lambert's, and the luminaires' area model).
//
// The region is the face clipped by the point's horizon, minus the solids' shadows on the face's
// plane; its boundary is returned as arcs (the vectors from the point to each piece's ends),
// oriented so that, with m = unit(to × from), a Lambertian face of luminance L gives
// E = L/2 · Σ θ · n·m (θ the angle between from and to, n the point's normal).
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// 2-D coordinates (u, v) on a face's plane, with e1 × e2 = the face's emission normal.
struct FaceFrame {
  Vec3 origin, e1, e2, normal;
  double offset = 0.0;
  Eigen::Vector2d flat(const Vec3& x) const {
    return Eigen::Vector2d((x - origin).dot(e1), (x - origin).dot(e2));
  }
  Vec3 lift(const Eigen::Vector2d& x) const { return origin + x.x() * e1 + x.y() * e2; }

  // The frame of `polygon` (non-empty, non-zero area): normal = polygon.normal().
  static FaceFrame of(const ConvexPolygon& polygon);
};

struct VisibleArc {
  Vec3 from, to;  // from the point to the piece's ends
};

// The arcs bounding the part of `face` (emitting along frame.normal) that `point` sees; none when
// the point is not in front of the face (within `tolerance`, m), sees none of it past its horizon,
// or all of it is hidden. The solid the point lies on never blocks it; a solid touching the face's
// plane from behind does not block it.
std::vector<VisibleArc> visibleBoundary(const ConvexPolygon& face, const FaceFrame& frame,
                                        const SamplePoint& point, const Scene& scene,
                                        double tolerance);

}  // namespace penumbra
