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
 * Tie rule (one rule everywhere): when an edge lies in a boundary plane of another region (and
 * that plane's edge in the first edge's plane: edge_in_plane), the two regions' visible sides
 * coincide or are opposite. Coincide: the edge is kept once, by the region of lowest index (the
 * source is lowest, then occluders in list order); opposite: the visible region is empty there
 * and the edge is dropped. So two boxes side by side drop their
 * shared contour edge, a duplicated occluder counts once, and an occluder edge collinear with
 * a source edge never leaks (docs/method.md, "The tie rule").
 *
 * Here: occluder contour edges, side planes, piece ends at crossings and the term of a piece. */

#include "occluders.cl"

/* The contour edge e of an active occluder, hole-oriented, relative to P (p and p_lo: its hi and
 * lo parts, PnPosition), and its ends' positions in *qa, *qb: an edge between a face that sees P
 * and one that does not. False when e
 * is not on the contour. Whether a face sees P is tested per edge rather than kept in a bit mask,
 * so that a solid may have any number of faces (a finely faceted sphere has hundreds). */
inline bool contour_edge(int e, PnOccluder o, float3 p, float3 p_lo, const PnSceneTables* tables,
                         float eps_length, float3* a, float3* b, PnPosition* qa, PnPosition* qb) {
  int4 ed = tables->edges[o.firstEdge + e];
  bool left_front = face_sees1(o, ed.z, tables, p.x, p.y, p.z, eps_length);
  bool right_front = face_sees1(o, ed.w, tables, p.x, p.y, p.z, eps_length);
  if (left_front == right_front) return false;
  /* Run it as the face that does not see P does: that face's loop goes from -> to when it is
   * the left face. */
  const PnPosition q_from = tables->occluderVertices[o.firstVertex + ed.x];
  const PnPosition q_to = tables->occluderVertices[o.firstVertex + ed.y];
  const float3 from = pn_from1(q_from, p, p_lo), to = pn_from1(q_to, p, p_lo);
  *a = left_front ? to : from;
  *b = left_front ? from : to;
  *qa = left_front ? q_to : q_from;
  *qb = left_front ? q_from : q_to;
  return true;
}

/* ---------------------------------------------------------------------------------------------
 * Side planes, piece ends and piece terms, each written once for a lane type T: float for one
 * point (the scalar path; names end in 1) and float8 for eight (the lane path; names end in 8),
 * with M the mask type comparisons give (int: 0 or 1; int8: 0 or -1). The two paths must agree
 * here bit for bit: the tie rule compares side planes, and a visible contour closes only where
 * both edges at a crossing compute the same vector. Masks combine with &, | and ! (not ~, which
 * turns a scalar 1 into -2), and select() reads both kinds. The scalar path's float3 forms
 * follow the definitions. */

/* The unit normal of the side plane through P and the segment (a, b), along cross(a, b); zero
 * where the plane is undefined: the segment is a point or its line passes through P. The cross
 * product is taken as cross(a, b − a), whose products are |a|·|b − a| rather than |a|·|b|. Side
 * planes are normalised once per point so that the tests need no square roots. Computed without
 * fma contraction and normalised by rsqrt (the arithmetic of PoCL's cross() and normalize()), the
 * open office's default and plain paths stay 8.3e-7 of E_unoccluded apart at worst; contracted
 * and normalised by a division they are 1.02e-6 apart at (11.35, 5.35) m, past culling_test's
 * bound of 1e-6. */
#define PN_DEFINE_SIDE_NORMAL(T, M, S)                                                  \
  inline void side_normal##S(T ax, T ay, T az, T bx, T by, T bz, T* mx, T* my, T* mz) { \
    _Pragma("OPENCL FP_CONTRACT OFF") T ex = bx - ax, ey = by - ay, ez = bz - az;       \
    T cx = ay * ez - az * ey, cy = az * ex - ax * ez, cz = ax * ey - ay * ex;           \
    T square = cx * cx + cy * cy + cz * cz;                                             \
    T la = sqrt(ax * ax + ay * ay + az * az), lb = sqrt(bx * bx + by * by + bz * bz);   \
    M none = sqrt(square) <= PN_EPS_REL * la * lb;                                      \
    T inverse = rsqrt(square);                                                          \
    *mx = select(cx * inverse, (T)(0.0f), none);                                        \
    *my = select(cy * inverse, (T)(0.0f), none);                                        \
    *mz = select(cz * inverse, (T)(0.0f), none);                                        \
  }

/* The point at parameter t of the edge a → b (one coordinate), measured from the nearer end:
 * the ends come back exactly (a + 1·(b − a) is not b in float), so that a visible contour still
 * closes where consecutive edges meet. An open contour leaves an error of about eps·|a| / size,
 * which for a small, distant source is 1e-5 of its illuminance instead of 1e-7. */
#define PN_DEFINE_EDGE_POINT(T, S)                                       \
  inline T edge_point##S(T a, T b, T t) {                                \
    return select(b - (1.0f - t) * (b - a), a + t * (b - a), t <= 0.5f); \
  }

/* Whether the edge (a, b), of lengths la and lb, lies in a plane through P with unit normal m,
 * from f0 = m·a and f1 = m·b: the sine of the angle between the plane and each end's direction
 * at most PN_TIE_REL (Tolerance::kKernelTie, 1e-6: a few times float's rounding of a side plane,
 * and a tenth of the kernel's general tolerance, so that what the tie rule keeps or drops is a
 * band that thin). */
#define PN_DEFINE_IN_PLANE(T, M, S)                                       \
  inline M in_plane##S(T f0, T f1, T la, T lb) {                          \
    return (fabs(f0) <= PN_TIE_REL * la) & (fabs(f1) <= PN_TIE_REL * lb); \
  }

/* Whether the edge (a, b) lies in the plane through P with unit normal m (in_plane of its ends,
 * the products written as every caller writes f0 and f1). The tie rule takes an edge and another
 * region's side plane as tied only when that plane's own edge also lies in the first edge's side
 * plane: one decision for the pair, the same at either edge. Tested one way only, the two edges
 * can disagree where their planes are about a tolerance apart (an end's sine is the planes'
 * angle times its distance from their common line over its length, which differs between the
 * edges): one edge drops itself as tied while the other, not tied, is covered, and the contour
 * is left open (a wall element seen past a desk's edge from the floor would give 13 times its E
 * in a band 1.5 µm wide: tests/occlusion_test.cpp). Untied, the two sign tests agree: the planes
 * are then about a tolerance apart, far beyond float's rounding. */
#define PN_DEFINE_EDGE_IN_PLANE(T, M, S)                                                      \
  inline M edge_in_plane##S(T mx, T my, T mz, T ax, T ay, T az, T bx, T by, T bz) {           \
    return in_plane##S(mx * ax + my * ay + mz * az, mx * bx + my * by + mz * bz,              \
                       sqrt(ax * ax + ay * ay + az * az), sqrt(bx * bx + by * by + bz * bz)); \
  }

/* The tie rule where an edge owned by region `owner` (normal along cross(a, b): m_edge) lies in
 * a side plane m of region v (`tied`, from in_plane): where the two visible sides coincide the
 * region of lower index keeps the edge, so v does not cover it when the owner comes first (the
 * lanes returned); where they are opposite the plane does not limit the edge, and the edge is
 * dropped by the region whose edge lies in the plane. */
#define PN_DEFINE_KEEPS_TIED_EDGE(T, M, S)                                                     \
  inline M keeps_tied_edge##S(M tied, T m_edge_x, T m_edge_y, T m_edge_z, T mx, T my, T mz,    \
                              int owner, int v) {                                              \
    return owner < v ? tied & (m_edge_x * mx + m_edge_y * my + m_edge_z * mz > 0.0f) : (M)(0); \
  }

/* Clips [*t0, *t1] to {t : f0 + t (f1 − f0) >= 0} in the lanes of `clip`, remembering in *id0
 * and *id1, per lane, the plane (its id) that set each end. Returns the lanes where the interval
 * is not empty (or not clipped). */
#define PN_DEFINE_CLIP_INTERVAL_ID(T, M, S)                                                \
  inline M clip_interval_id##S(T f0, T f1, M clip, int id, T* t0, T* t1, M* id0, M* id1) { \
    M n0 = f0 < 0.0f, n1 = f1 < 0.0f;                                                      \
    M enters = clip & n0 & !n1, leaves = clip & !n0 & n1;                                  \
    if (pn_any(enters | leaves)) { /* most planes do not cross the edge: no division */    \
      T t = f0 / (f0 - f1);                                                                \
      M up0 = enters & (t > *t0), up1 = leaves & (t < *t1);                                \
      *t0 = select(*t0, t, up0);                                                           \
      *t1 = select(*t1, t, up1);                                                           \
      *id0 = select(*id0, (M)(id), up0);                                                   \
      *id1 = select(*id1, (M)(id), up1);                                                   \
    }                                                                                      \
    return !(clip & n0 & n1) & (*t1 > *t0);                                                \
  }

/* The tie rule reads an occluder's contour edge within the tie tolerance of an S' edge's side
 * plane m as lying in it: the edge is dropped, and the S' edge's piece ends where the planes of
 * the occluder's edges beside it cross m. Those edges must then end there too, so the shared
 * vertex a (from P) is moved into m, along u, the direction in the face's plane across the S'
 * edge: a − (m·a)/(m·u) u, which moves the vertex's image on the face onto the S' edge's line and
 * leaves the rest of the visible region as it is. Where m is nearly the face's plane (m·u below
 * PN_SNAP_ACROSS_MIN: P within 0.06° of the plane) it moves along m instead. Left apart, the
 * visible contour stays open by up to the tie tolerance (1e-6 of the distance), which costs up
 * to 1e-6 rad of Lambert's terms: several % of E where they cancel several hundredfold (a panel
 * seen nearly edge-on past a bezel's lip just inside its edge: tests/near_tie_test.cpp). */
#define PN_SNAP_ACROSS_MIN 1e-3f
#define PN_DEFINE_SNAP_END(T, M, S)                                                               \
  inline void snap_end##S(T mx, T my, T mz, T ux, T uy, T uz, M use, T* ax, T* ay, T* az) {       \
    T across = mx * ux + my * uy + mz * uz;                                                       \
    M along_m = fabs(across) < PN_SNAP_ACROSS_MIN;                                                \
    ux = select(ux, mx, along_m);                                                                 \
    uy = select(uy, my, along_m);                                                                 \
    uz = select(uz, mz, along_m);                                                                 \
    T k = (mx * *ax + my * *ay + mz * *az) / select(across, (T)(1.0f), along_m);                  \
    *ax = select(*ax, *ax - k * ux, use);                                                         \
    *ay = select(*ay, *ay - k * uy, use);                                                         \
    *az = select(*az, *az - k * uz, use);                                                         \
  }                                                                                               \
  /* u for the S' edge c → d (from P) of a face with unit normal n: unit(n × (d − c)). */    \
  inline void edge_across##S(float3 n, T cx, T cy, T cz, T dx, T dy, T dz, T* ux, T* uy, T* uz) { \
    T ex = dx - cx, ey = dy - cy, ez = dz - cz;                                                   \
    T x = n.y * ez - n.z * ey, y = n.z * ex - n.x * ez, z = n.x * ey - n.y * ex;                  \
    T inverse = rsqrt(fmax(x * x + y * y + z * z, (T)(1e-30f)));                                  \
    *ux = x * inverse;                                                                            \
    *uy = y * inverse;                                                                            \
    *uz = z * inverse;                                                                            \
  }

/* Where a visible piece ends because another region's side plane crosses the edge, the boundary
 * turns onto that region's edge, whose piece starts at the same direction: the line where the
 * two side planes meet. Both edges take it as the cross product of the two unit normals in one
 * order (that of their plane ids, self and other), so the two get the same vector bit for bit
 * and the visible contour closes; ends computed on each edge from its own parameter t would
 * leave a gap of a few roundings, and a gap of δ rad costs about L·δ however small the source
 * looks (tests/distant_source_test.cpp). turn_to_point then points it to the side of the edge's
 * own point p at t, in the lanes of `set` (the lanes it turns are returned); where the planes are
 * nearly parallel (sine below PN_EPS_REL) the line is ill-defined and p stays. Its length does not
 * matter (piece_term). */
#define PN_DEFINE_CROSSING(T, M, S)                                                                \
  inline void crossing_direction##S(T msx, T msy, T msz, int self, T mox, T moy, T moz, int other, \
                                    T* dx, T* dy, T* dz) {                                         \
    const bool first = self < other;                                                               \
    T px = first ? msx : mox, py = first ? msy : moy, pz = first ? msz : moz;                      \
    T qx = first ? mox : msx, qy = first ? moy : msy, qz = first ? moz : msz;                      \
    *dx = py * qz - pz * qy;                                                                       \
    *dy = pz * qx - px * qz;                                                                       \
    *dz = px * qy - py * qx;                                                                       \
  }                                                                                                \
  inline M turn_to_point##S(T dx, T dy, T dz, M set, T* px, T* py, T* pz) {                        \
    M use = set & (dx * dx + dy * dy + dz * dz > PN_EPS_REL * PN_EPS_REL);                         \
    if (!pn_any(use)) return use;                                                                  \
    T sign = select((T)(1.0f), (T)(-1.0f), dx * *px + dy * *py + dz * *pz < 0.0f);                 \
    *px = select(*px, sign * dx, use);                                                             \
    *py = select(*py, sign * dy, use);                                                             \
    *pz = select(*pz, sign * dz, use);                                                             \
    return use;                                                                                    \
  }

/* Lambert's term of the piece (a → b) of an edge, as edge_term8: the great circle through the
 * two ends as computed, so that pieces meeting at a crossing point close the contour exactly
 * (the edge's own circle and the other edge's miss the computed crossing by a rounding each, and
 * would leave that gap). The angle and the circle's normal must be good to a rounding of
 * themselves, not of a radian: the terms of a small source nearly cancel, and an error δ in one
 * angle costs about L·δ. edge_term8 gets that from b − a, exact where a and b are nearly
 * parallel; the ends of a piece may be a crossing direction and a point of any length, so the
 * cross product is made accurate instead (diff_of_products). A face of polynomial luminance takes
 * the moment term (luminance_moments.cl) on the same cross product, negated to b × a. */
#define PN_DEFINE_PIECE_TERM(T, S)                                                                \
  inline T piece_term##S(T ax, T ay, T az, T bx, T by, T bz, T nx, T ny, T nz,                    \
                         const PnEmission* em) {                                                  \
    T cx = diff_of_products##S(ay, bz, az, by), cy = diff_of_products##S(az, bx, ax, bz),         \
      cz = diff_of_products##S(ax, by, ay, bx);                                                   \
    T s = sqrt(cx * cx + cy * cy + cz * cz);                                                      \
    T term = em->order >= 0                                                                       \
                 ? moment_term##S(ax, ay, az, bx, by, bz, -cx, -cy, -cz, s, nx, ny, nz, 0, em, 0) \
                 : -atan2(s, ax * bx + ay * by + az * bz) * (nx * cx + ny * cy + nz * cz) / s;    \
    return select(term, (T)(0.0f), s <= 0.0f);                                                    \
  }

/* A face small against its distance from P (lambert.cl, PN_SMALL_FACE) has pieces whose terms
 * cancel to E as its edges' do, and takes them relative to its reference point C (arc_term.cl,
 * T') in the lanes where it is small. Each end of a piece is then an offset α from C with C + α
 * on the end's ray from P: the exact vertex offset (vertex_offset) at a vertex of the face, the
 * same interpolation of two such offsets at a point between them (a horizon crossing, a piece end
 * that is not a crossing: edge_point on the offsets, with the parameter the vectors from P use),
 * and elsewhere (a crossing direction, an occluder's point, an aperture's corner: any vector p
 * from P, of any length) p taken along its ray to the face's plane, centre_offset:
 * C + α = s p, s = N·C / N·p (N the face's normal), α = fma(p, s, −C), good to a rounding of
 * itself, so that C + α keeps p's direction to a rounding of α rather than of C. An end whose ray
 * meets the plane more than 2|C| from C (PN_PIECE_FAR: an ill-conditioned crossing of two nearly
 * parallel side planes may point far from the face, or along the plane) is taken to the sphere of
 * radius |C| instead, s = |C| / |p|, so that its terms and their roundings stay of the order of
 * the face's. Pieces that meet at a point compute the same α there, so the part T' leaves
 * out of every arc telescopes around the visible contour as around a whole face; and every α lies
 * in the face's plane, so that two ends that meet only to within a small angle (a sliver the tie
 * rule keeps or drops, kernels/contour.cl's head) are as near in α as in direction, and the
 * telescoping part leaves no more than Lambert's terms would for that gap. Vertices and their
 * interpolations keep E to a few roundings of itself as whole_face8 does; what is left is the
 * direction of the other ends, a rounding of the vectors from P each (docs/method.md, the
 * precision note). */
/* A piece end two side planes cross at, in the lanes of the planar form, is the crossing of the
 * two edges' lines in the face's plane (planar_crossing): the crossing direction of two side planes
 * through P is good to a fraction of a rounding of a radian, but seen from e above the plane that
 * moves its image on the plane by r/sin e times as much, where the two edges' lines in the plane
 * are good to a rounding of their ends. An occluder's edge takes part where both its ends' rays
 * meet the plane at a sine of PN_PLANAR_END_MIN or more, and two lines that cross at a sine below
 * PN_PLANAR_CROSSING_MIN keep the side planes' direction. Which edges meet is still decided by
 * the side planes, whose rounding moves a decision's place on the plane by about u |p|² / h (u
 * |p| / sin e from e above it): a crossing within PN_PLANAR_SNAP |p|² / h of an end of either
 * line (four such roundings) is that end, so that where an edge passes that close to another
 * edge's end, the edges meeting there close the contour whichever of them the side planes chose.
 * Moving a true crossing by that much moves E by less than the rounding that blurs the choice. */
#define PN_PLANAR_END_MIN 1e-3f
#define PN_PLANAR_CROSSING_MIN 1e-4f
#define PN_PLANAR_SNAP 2.4e-7f
#define PN_PIECE_FAR 4.0f /* |α|² / |C|² beyond which an end goes to the sphere of radius |C| */
#define PN_DEFINE_PIECE_FORM(T, M, S)                                                                     \
  typedef struct {                                                                                        \
    const PnEmission* em;     /* how the face emits */                                                    \
    PnCentre##S centre;       /* its reference point, in the lanes of `small` */                          \
    float4 plane;             /* the face's plane (unit normal N in xyz) */                               \
    T height;                 /* N·C */                                                                  \
    M small;                  /* lanes where the face is small against its distance */                    \
    PnPlanarFrame##S* planar; /* in the lanes of planar_lanes (not small): the planar form */             \
    M planar_lanes;                                                                                       \
    M crossing_lanes; /* planar_lanes, and the band above it where crossings are taken in the             \
                         plane */                                                                         \
  } PnPieceForm##S;                                                                                       \
  /* A boundary edge's ends in the face's plane (planar_crossing), and the lanes where each is            \
   * there. */                                                                                            \
  typedef struct {                                                                                        \
    T ax, ay, az, bx, by, bz;                                                                             \
    M a_in, b_in;                                                                                         \
  } PnPlanarLine##S;                                                                                      \
  inline void centre_offset##S(const PnPieceForm##S* form, T px, T py, T pz, T* ox, T* oy,                \
                               T* oz) {                                                                   \
    const PnCentre##S* c = &form->centre;                                                                 \
    T s = form->height / (form->plane.x * px + form->plane.y * py + form->plane.z * pz);                  \
    T x = fma(px, s, -c->x), y = fma(py, s, -c->y), z = fma(pz, s, -c->z);                                \
    M far = !(x * x + y * y + z * z <= PN_PIECE_FAR * c->norm2);                                          \
    if (pn_any(far)) {                                                                                    \
      s = sqrt(c->norm2 / (px * px + py * py + pz * pz));                                                 \
      x = select(x, fma(px, s, -c->x), far);                                                              \
      y = select(y, fma(py, s, -c->y), far);                                                              \
      z = select(z, fma(pz, s, -c->z), far);                                                              \
    }                                                                                                     \
    *ox = x;                                                                                              \
    *oy = y;                                                                                              \
    *oz = z;                                                                                              \
  }                                                                                                       \
  /* N·p for an end p (from P): what planar_point and planar_end read where no rounder figure of         \
   * N·p is known (planar_depth, for an occluder's vertex). */                                           \
  inline T plane_dot##S(const PnPieceForm##S* form, T px, T py, T pz) {                                   \
    return form->plane.x * px + form->plane.y * py + form->plane.z * pz;                                  \
  }                                                                                                       \
  /* An end p (from P) of a piece taken by the planar form, in the lanes of `project` (an                 \
   * occluder's point or a crossing direction, not a point of S'), along its ray to the face's            \
   * plane: p · h / (−np), np = N·p. An end whose ray does not meet the plane in front of P stays.    \
   */                                                                                                     \
  inline void planar_point##S(const PnPieceForm##S* form, M project, T np, T* px, T* py, T* pz) {         \
    const M use = project & (np < 0.0f);                                                                  \
    if (!pn_any(use)) return;                                                                             \
    const T s = -form->planar->h / np;                                                                    \
    *px = select(*px, *px * s, use);                                                                      \
    *py = select(*py, *py * s, use);                                                                      \
    *pz = select(*pz, *pz * s, use);                                                                      \
  }                                                                                                       \
  /* An occluder edge's end p (from P, np = N·p) taken to the face's plane for planar_crossing, in       \
   * the lanes where its ray meets the plane clearly in front of P (returned). */                         \
  inline M planar_end##S(const PnPieceForm##S* form, T np, T* px, T* py, T* pz) {                         \
    const M ok = np < -PN_PLANAR_END_MIN * sqrt(*px * *px + *py * *py + *pz * *pz);                       \
    planar_point##S(form, ok, np, px, py, pz);                                                            \
    return ok;                                                                                            \
  }                                                                                                       \
  /* *p moved to v in the lanes of `use` where c is within √reach2 of v (returned). */                  \
  inline M snap_to##S(T cx, T cy, T cz, T vx, T vy, T vz, M use, T reach2, T* px, T* py, T* pz) {         \
    const T dx = cx - vx, dy = cy - vy, dz = cz - vz;                                                     \
    const M at = use & (dx * dx + dy * dy + dz * dz < reach2);                                            \
    *px = select(*px, vx, at);                                                                            \
    *py = select(*py, vy, at);                                                                            \
    *pz = select(*pz, vz, at);                                                                            \
    return at;                                                                                            \
  }                                                                                                       \
  /* Where two boundary edges cross, the point in the face's plane: the line a1 → b1 (the edge of       \
   * the lower plane id) meets the line a2 → b2, both in the plane (a face's edge, or an                \
   * occluder's edge through planar_end), at a1 + t (b1 − a1), t = ((a2 − a1) × v)·N / (u × v)·N, \
   * or, within PN_PLANAR_SNAP |p|² / h of an end of either line that lies in the plane, that end.       \
   * Where the lines are near parallel or an end is not in the plane (an edge seen end-on), the           \
   * crossing direction *p taken to the plane, if that is within the same reach of an end, is that        \
   * end; elsewhere *p stays a direction. Both edges that meet there compute it from the same ends        \
   * in the same order, so they get the same point. Set in *p in the lanes of `use` returned. */          \
  inline M planar_crossing##S(const PnPieceForm##S* form, const PnPlanarLine##S* l1,                      \
                              const PnPlanarLine##S* l2, M use, T* px, T* py, T* pz) {                    \
    const float3 N = form->plane.xyz;                                                                     \
    const T a1x = l1->ax, a1y = l1->ay, a1z = l1->az, b1x = l1->bx, b1y = l1->by, b1z = l1->bz;           \
    const T a2x = l2->ax, a2y = l2->ay, a2z = l2->az, b2x = l2->bx, b2y = l2->by, b2z = l2->bz;           \
    const T ux = b1x - a1x, uy = b1y - a1y, uz = b1z - a1z;                                               \
    const T vx = b2x - a2x, vy = b2y - a2y, vz = b2z - a2z;                                               \
    const T wx = a2x - a1x, wy = a2y - a1y, wz = a2z - a1z;                                               \
    const T den =                                                                                         \
        N.x * (uy * vz - uz * vy) + N.y * (uz * vx - ux * vz) + N.z * (ux * vy - uy * vx);                \
    const T num =                                                                                         \
        N.x * (wy * vz - wz * vy) + N.y * (wz * vx - wx * vz) + N.z * (wx * vy - wy * vx);                \
    const M lines = use & l1->a_in & l1->b_in & l2->a_in & l2->b_in;                                      \
    const M ok =                                                                                          \
        lines & (fabs(den) > PN_PLANAR_CROSSING_MIN * sqrt((ux * ux + uy * uy + uz * uz) *                \
                                                           (vx * vx + vy * vy + vz * vz)));               \
    const T t = num / select((T)(1.0f), den, ok);                                                         \
    T x = *px, y = *py, z = *pz;                                                                          \
    const T np = plane_dot##S(form, x, y, z);                                                             \
    const M direction = use & !ok & (np < 0.0f);                                                          \
    planar_point##S(form, direction, np, &x, &y, &z);                                                     \
    x = select(x, a1x + t * ux, ok), y = select(y, a1y + t * uy, ok),                                     \
    z = select(z, a1z + t * uz, ok);                                                                      \
    const T cx = x, cy = y, cz = z;                                                                       \
    const T reach = PN_PLANAR_SNAP * (x * x + y * y + z * z) / form->planar->h;                           \
    const T reach2 = reach * reach;                                                                       \
    /* the ends in reverse order of priority: the first line's a end last, so that it wins */             \
    M snapped = snap_to##S(cx, cy, cz, b2x, b2y, b2z, l2->b_in, reach2, &x, &y, &z);                      \
    snapped |= snap_to##S(cx, cy, cz, a2x, a2y, a2z, l2->a_in, reach2, &x, &y, &z);                       \
    snapped |= snap_to##S(cx, cy, cz, b1x, b1y, b1z, l1->b_in, reach2, &x, &y, &z);                       \
    snapped |= snap_to##S(cx, cy, cz, a1x, a1y, a1z, l1->a_in, reach2, &x, &y, &z);                       \
    const M done = ok | (direction & snapped);                                                            \
    *px = select(*px, x, done);                                                                           \
    *py = select(*py, y, done);                                                                           \
    *pz = select(*pz, z, done);                                                                           \
    return done;                                                                                          \
  }                                                                                                       \
  /* The term of the piece p0 → p1 (from P), whose ends are o0 and o1 from C (read in the small         \
   * lanes only). In the lanes of form->planar_lanes by the planar form, the ends of project0 and         \
   * project1 taken to the face's plane (planar_point, with np0 = N·p0 and np1 = N·p1) and the          \
   * piece's Δψ added to the frame's sum in the lanes of `use`. */                                      \
  inline T form_piece_term##S(const PnPieceForm##S* form, T p0x, T p0y, T p0z, T p1x, T p1y,              \
                              T p1z, T o0x, T o0y, T o0z, T o1x, T o1y, T o1z, T nx, T ny, T nz,          \
                              M project0, M project1, T np0, T np1, M use) {                              \
    T relative = 0.0f;                                                                                    \
    if (pn_any(form->small))                                                                              \
      relative = arc_term##S(&form->centre, o0x, o0y, o0z, o1x, o1y, o1z, nx, ny, nz, form->em);          \
    if (pn_all(form->small)) return relative;                                                             \
    T term = 0.0f;                                                                                        \
    if (!pn_all(form->planar_lanes))                                                                      \
      term = piece_term##S(p0x, p0y, p0z, p1x, p1y, p1z, nx, ny, nz, form->em);                           \
    if (pn_any(form->planar_lanes)) {                                                                     \
      planar_point##S(form, project0, np0, &p0x, &p0y, &p0z);                                             \
      planar_point##S(form, project1, np1, &p1x, &p1y, &p1z);                                             \
      T dpsi;                                                                                             \
      const T planar =                                                                                    \
          planar_term##S(p0x, p0y, p0z, p1x, p1y, p1z, form->planar, nx, ny, nz, form->em, &dpsi);        \
      form->planar->dpsi_sum += select((T)(0.0f), dpsi, use & form->planar_lanes);                        \
      term = select(term, planar, form->planar_lanes);                                                    \
    }                                                                                                     \
    return select(term, relative, form->small);                                                           \
  }

#define PN_DEFINE_CONTOUR_TWINS(T, M, S) \
  PN_DEFINE_SIDE_NORMAL(T, M, S)         \
  PN_DEFINE_EDGE_POINT(T, S)             \
  PN_DEFINE_IN_PLANE(T, M, S)            \
  PN_DEFINE_EDGE_IN_PLANE(T, M, S)       \
  PN_DEFINE_SNAP_END(T, M, S)            \
  PN_DEFINE_KEEPS_TIED_EDGE(T, M, S)     \
  PN_DEFINE_CLIP_INTERVAL_ID(T, M, S)    \
  PN_DEFINE_CROSSING(T, M, S)            \
  PN_DEFINE_PIECE_TERM(T, S)             \
  PN_DEFINE_PIECE_FORM(T, M, S)
PN_DEFINE_CONTOUR_TWINS(float, int, 1)   /* one body for the scalar path */
PN_DEFINE_CONTOUR_TWINS(float8, int8, 8) /* and for eight lanes */
#undef PN_DEFINE_CONTOUR_TWINS
#undef PN_DEFINE_SIDE_NORMAL
#undef PN_DEFINE_EDGE_POINT
#undef PN_DEFINE_IN_PLANE
#undef PN_DEFINE_EDGE_IN_PLANE
#undef PN_DEFINE_SNAP_END
#undef PN_DEFINE_KEEPS_TIED_EDGE
#undef PN_DEFINE_CLIP_INTERVAL_ID
#undef PN_DEFINE_CROSSING
#undef PN_DEFINE_PIECE_TERM
#undef PN_DEFINE_PIECE_FORM

/* The scalar path's float3 forms. */
inline float3 side_normal(float3 a, float3 b) {
  float x, y, z;
  side_normal1(a.x, a.y, a.z, b.x, b.y, b.z, &x, &y, &z);
  return (float3)(x, y, z);
}

inline bool no_plane(float3 m) {
  return m.x == 0.0f && m.y == 0.0f && m.z == 0.0f;
}

inline float3 edge_point(float3 a, float3 b, float t) {
  return (float3)(edge_point1(a.x, b.x, t), edge_point1(a.y, b.y, t), edge_point1(a.z, b.z, t));
}

/* The end of a piece at the crossing of side planes m_self (id `self`) and m_other (`other`),
 * own_point where the crossing is ill-defined (*turned 0). */
#define PN_ID_VERTEX -1 /* a piece end at the edge's own end, or at the horizon */
inline float3 crossing_point(float3 m_self, int self, float3 m_other, int other, float3 own_point,
                             int* turned) {
  float dx, dy, dz, x = own_point.x, y = own_point.y, z = own_point.z;
  crossing_direction1(m_self.x, m_self.y, m_self.z, self, m_other.x, m_other.y, m_other.z, other,
                      &dx, &dy, &dz);
  *turned = turn_to_point1(dx, dy, dz, 1, &x, &y, &z);
  return (float3)(x, y, z);
}

inline float3 centre_offset(const PnPieceForm1* form, float3 p) {
  float x, y, z;
  centre_offset1(form, p.x, p.y, p.z, &x, &y, &z);
  return (float3)(x, y, z);
}

/* form_piece_term1 of the piece a → b, whose ends are off the face's plane where project_a and
 * project_b say. */
inline float form_piece_term(const PnPieceForm1* form, float3 a, float3 b, float3 oa, float3 ob,
                             float3 n, int project_a, int project_b, float np_a, float np_b) {
  return form_piece_term1(form, a.x, a.y, a.z, b.x, b.y, b.z, oa.x, oa.y, oa.z, ob.x, ob.y, ob.z,
                          n.x, n.y, n.z, project_a, project_b, np_a, np_b, 1);
}
