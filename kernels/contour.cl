/* The contour of the visible region, shared by both penumbra paths (Nishita §2.5(2),
 * docs/method.md): the visible region is
 * S' \ ∪ O_k, S' the face clipped by the horizon, O_k occluder k's contour as seen from P.
 * Every boundary edge is oriented with the visible side on its left as seen from P; for such an
 * edge (a → b) the visible side is {x : cross(a, b)·x < 0}. Its boundary is
 *   (a) the parts of S' edges in no O_k, and
 *   (b) the parts of each O_k's contour edges inside S' and in no other O_j, run in the
 *       direction of the face that does not see P (so the hole is on their right).
 * Each edge against a convex cone is one parameter interval (Cyrus–Beck on planes through P).
 *
 * Tie rule (one rule everywhere): when an edge lies in a boundary plane of another region, the
 * two regions' visible sides coincide or are opposite. Coincide: the edge is kept once, by the
 * region of lowest index (the source is lowest, then occluders in list order); opposite: the
 * visible region is empty there and the edge is dropped. So two boxes side by side drop their
 * shared contour edge, a duplicated occluder counts once, and an occluder edge collinear with
 * a source edge never leaks (docs/method.md, "The tie rule").
 *
 * Here: occluder contour edges, side planes, piece ends at crossings and the term of a piece. */

#include "prelude.cl"

/* The contour edge e of an active occluder, hole-oriented, relative to P. False when e is not
 * on the contour. */
inline bool faces_point(PnOccluder o, int face, float3 p, const PnSceneTables* tables,
                        float eps_length) {
  float4 pl = tables->planes[o.firstPlane + face];
  return dot(pl.xyz, p) - pl.w > eps_length;
}

/* Whether a face sees P is tested per edge rather than kept in a bit mask, so that a solid may
 * have any number of faces (a finely faceted sphere has hundreds). */
inline bool contour_edge(int e, PnOccluder o, float3 p, const PnSceneTables* tables,
                         float eps_length, float3* a, float3* b) {
  int4 ed = tables->edges[o.firstEdge + e];
  bool left_front = faces_point(o, ed.z, p, tables, eps_length);
  bool right_front = faces_point(o, ed.w, p, tables, eps_length);
  if (left_front == right_front) return false;
  /* Run it as the face that does not see P does: that face's loop goes from -> to when it is
   * the left face. */
  float3 from = tables->occluderVertices[o.firstVertex + ed.x].xyz - p;
  float3 to = tables->occluderVertices[o.firstVertex + ed.y].xyz - p;
  if (left_front) {
    *a = to;
    *b = from;
  } else {
    *a = from;
    *b = to;
  }
  return true;
}

/* A side plane through P and the segment (a, b) is undefined when the segment is a point or
 * its line passes through P. */
inline bool degenerate_side(float3 m, float3 a, float3 b) {
  return length(m) <= PN_EPS_REL * length(a) * length(b);
}

/* The unit normal of the side plane through P and (a, b); zero when it is undefined. Side
 * planes are normalised once per point so that the tests below need no square roots. */
inline float3 side_normal(float3 a, float3 b) {
  float3 m = cross(a, b - a);
  return degenerate_side(m, a, b) ? (float3)(0.0f) : normalize(m);
}

inline bool no_plane(float3 m) {
  return m.x == 0.0f && m.y == 0.0f && m.z == 0.0f;
}

/* Does the edge (a, b), of lengths la and lb, lie in the plane through P with unit normal m?
 * The test reads as the sine of the angle between the plane and each end's direction. */
inline bool in_plane(float f0, float f1, float la, float lb) {
  return fabs(f0) <= PN_EPS_REL * la && fabs(f1) <= PN_EPS_REL * lb;
}

/* The point at parameter t of the edge a → b, measured from the nearer end: the ends come back
 * exactly (a + 1·(b − a) is not b in float), so that a visible contour still closes where
 * consecutive edges meet. An open contour leaves an error of about eps·|a| / size, which for a
 * small, distant source is 1e-5 of its illuminance instead of 1e-7. */
inline float3 edge_point(float3 a, float3 b, float t) {
  return t <= 0.5f ? a + t * (b - a) : b - (1.0f - t) * (b - a);
}

/* Where a visible piece ends because another region's side plane crosses the edge, the boundary
 * turns onto that region's edge, whose piece starts at the same direction: the line where the two
 * side planes meet. Both edges take it as the cross product of the two unit normals in one order
 * (that of their plane ids), so the two get the same vector bit for bit and the visible contour
 * closes. Ends computed on each edge from its own parameter t leave a gap of a few float
 * roundings, and a gap of δ rad costs about L·δ however small the source looks: for a 0.6 m
 * panel 10 m away, seen past a chair back 0.4 m from P, that was up to 2e-3 of the panel's
 * illuminance (tests/distant_source_test.cpp; now 6e-5, the float rounding of the unoccluded
 * formula there). Its length does not matter (piece_term). Where the planes are nearly parallel
 * (sine below PN_EPS_REL) the line is ill-defined and both edges keep their own point. */
#define PN_ID_VERTEX -1 /* a piece end at the edge's own end, or at the horizon */
inline float3 crossing_point(float3 m_self, int id_self, float3 m_other, int id_other,
                             float3 own_point) {
  float3 d = id_self < id_other ? cross(m_self, m_other) : cross(m_other, m_self);
  if (!(dot(d, d) > PN_EPS_REL * PN_EPS_REL)) return own_point;
  return dot(d, own_point) < 0.0f ? -d : d;
}

/* x·y − z·w to about one rounding of the result (Kahan's algorithm with fma), where the plain
 * products would leave the rounding of the larger of them. */
inline float diff_of_products(float x, float y, float z, float w) {
  float zw = z * w;
  return fma(x, y, -zw) + fma(-z, w, zw);
}

/* cross(p, q), each component to about one rounding of itself. */
inline float3 accurate_cross(float3 p, float3 q) {
  return (float3)(diff_of_products(p.y, q.z, p.z, q.y), diff_of_products(p.z, q.x, p.x, q.z),
                  diff_of_products(p.x, q.y, p.y, q.x));
}

/* Lambert's term of the piece (p0 → p1) of an edge, as edge_term8: the great circle through the
 * two ends as computed, so that pieces meeting at a crossing point close the contour exactly (the
 * edge's own circle and the other edge's miss the computed crossing by a rounding each, and would
 * leave that gap). The angle and the circle's normal must be good to a rounding of themselves,
 * not of a radian: the terms of a small source nearly cancel, and an error δ in one angle costs
 * about L·δ. edge_term8 gets that from b − a, exact where a and b are nearly parallel; the ends of
 * a piece may be a crossing direction and a point of any length, so the cross product is made
 * accurate instead. */
inline float piece_term(float3 p0, float3 p1, float3 n) {
  float3 c = accurate_cross(p0, p1);
  float s = length(c);
  if (!(s > 0.0f)) return 0.0f;
  return -atan2(s, dot(p0, p1)) * dot(n, c) / s;
}

/* Clips [*t0, *t1] to {t : f0 + t (f1 - f0) >= 0}, remembering which plane (its id) set each
 * end. */
inline void clip_interval_id(float f0, float f1, int id, float* t0, float* t1, int* id0, int* id1) {
  if (f0 >= 0.0f && f1 >= 0.0f) return;
  if (f0 < 0.0f && f1 < 0.0f) {
    *t1 = *t0 - 1.0f;
    return;
  }
  float t = f0 / (f0 - f1);
  if (f0 < 0.0f) {
    if (t > *t0) {
      *t0 = t;
      *id0 = id;
    }
  } else if (t < *t1) {
    *t1 = t;
    *id1 = id;
  }
}
