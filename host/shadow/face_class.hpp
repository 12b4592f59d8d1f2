#pragma once
// Nishita & Nakamae's face classes (eq. 3 for area sources, eq. 4 for polyhedron sources): how a
// receiving face lies towards a source, decided once per (face, source) before any sample.
//   A  the whole source is in the face's positive space: lit from all of it (no horizon cut);
//   B  the face's plane cuts the source: a point sees at most the part above its horizon;
//   C  the face receives nothing from the source (the source is behind the face, or the face
//      is behind an area source): every sample on it gets 0 without entering the integral.
#include <span>

#include "geometry/convex_polyhedron.hpp"

namespace penumbra {

enum class FaceClass { A, B, C };

// eq. 3: `face` receives, `source` is an area source emitting towards its normal.
FaceClass classifyFace(const ConvexPolygon& face, const ConvexPolygon& source, double tolerance);
// eq. 4: a polyhedron source, all faces bright (it has no back side).
FaceClass classifyFace(const ConvexPolygon& face, const ConvexPolyhedron& source, double tolerance);

// The same question for one sample point with its normal (the face through the point), against
// the vertices of an emitting face with emission plane `emission`. C only when the answer is 0
// for certain: every vertex on or below the point's horizon, or the point on or behind the
// emitting plane.
FaceClass classifyPoint(const Vec3& point, const Vec3& normal, std::span<const Vec3> sourceVertices,
                        const Plane& emission);

}  // namespace penumbra
