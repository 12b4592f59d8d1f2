#pragma once
// Umbra and penumbra volumes of one occluder for one source (Nishita & Nakamae §2.3, Table 1),
// as sets of planes. Both are convex and unbounded away from the source:
//   penumbra volume  {P : the pyramid conv(P, source) meets the occluder V}
//                    = V + cone(V − source); outside it, V hides nothing of the source.
//   umbra volume     ∩ over source vertices Q of  V + cone(V − Q)  (the shadow volume of each
//                    vertex): P inside sees no vertex, hence (V convex) none of the source.
// Their planes are the three kinds of Table 1: through a source vertex and an occluder edge (Ŝ),
// through an occluder vertex and a source edge (S̄), and the occluder's own faces (S).
//
// Construction (and why it is robust): rather than select planes by the sign rules of Table 1,
// every candidate plane of the three kinds is generated and kept when it is *valid*, i.e. when
// the half-space provably holds the volume; validity is decided on the generators (vertex
// differences), with the tolerance policy of geometry/tolerance.hpp. For the penumbra volume a
// missing plane only makes the volume larger (more samples take the exact penumbra path); for the
// umbra volume an extra plane only makes it smaller. So a degenerate candidate (collinear points,
// an occluder touching the source plane, a flat occluder) is dropped without harm, and each test
// errs on the safe side: no blocking occluder is ever missed, no point that sees part of the
// source is ever called umbra.
#include <vector>

#include "geometry/convex_polyhedron.hpp"
#include "geometry/tolerance.hpp"

namespace penumbra {

struct ShadowVolume {
  // Closed inside: signedDistance <= 0 for every plane. Empty `penumbra` would mean the whole
  // space; an occluder always has at least its own faces, so it does not happen in practice.
  std::vector<Plane> penumbra;
  // Empty when no umbra is claimed (a degenerate pair, or no point can be fully hidden).
  std::vector<Plane> umbra;

  // Within `margin` (m) of the penumbra volume: samples here may be shaded by the occluder.
  bool mayShade(const Vec3& p, double margin) const;
  // Deeper than `margin` (m) inside the umbra volume: the occluder hides the whole source.
  bool hides(const Vec3& p, double margin) const;
};

// An area source (convex polygon emitting towards its normal) and an occluder already clipped to
// the source's front half-space (what ConvexPolyhedron::clipped by the flipped source plane
// gives; Nishita: "the portion of the positive-space of S_e").
ShadowVolume shadowVolume(const ConvexPolygon& source, const ConvexPolyhedron& occluder,
                          const Tolerance& tolerance);
// A polyhedron source (all faces bright); the occluder must not intersect it.
ShadowVolume shadowVolume(const ConvexPolyhedron& source, const ConvexPolyhedron& occluder,
                          const Tolerance& tolerance);

}  // namespace penumbra
