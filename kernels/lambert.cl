/* Lambert's contour integral for an unoccluded face (Nishita & Nakamae, §2.5; docs/method.md).
 *
 * For a point P with unit normal n and the visible part R of a source face of luminance L,
 * Lambert's contour integral gives  E = (L/2) · Σ θ_i · n·unit(b_i × a_i)  over the boundary
 * edges (a_i → b_i) of R (vectors from P) oriented with R on their left as seen from P, where
 * θ_i = atan2(|a_i × b_i|, a_i·b_i). Only directions matter, so every edge is integrated on the
 * 3-D segment it comes from: a source edge, the horizon chord, or an occluder's contour edge.
 * Here: one edge's term in eight lanes, and the face clipped by each lane's horizon. */

#include "arc_term.cl"
#include "planar_term.cl"

/* cross(b, a) is computed as cross(b − a, a): for a short edge far from P, a and b are long and
 * nearly parallel, b − a is exact in float (Sterbenz) and short, and the products are |e|·|a|
 * instead of |a|·|b|. For a 0.6 m panel 10 m away this takes the term's relative error from
 * about 2e-6 to 1e-7, which matters because the terms of a distant source nearly cancel. (The
 * penumbra paths integrate pieces of edges with piece_term, which keeps this accuracy for ends
 * that are not vertices.) A zero-length edge, or one whose line passes through P, spans no solid
 * angle. A face of polynomial luminance takes the moment term (luminance_moments.cl) on the same
 * cross product. A small face far from P takes arc_term8 instead (contour_term8, below). */
inline float8 edge_term8(float8 ax, float8 ay, float8 az, float8 bx, float8 by, float8 bz,
                         float8 nx, float8 ny, float8 nz, const PnEmission* em) {
  float8 ex = bx - ax, ey = by - ay, ez = bz - az;
  float8 cx = ey * az - ez * ay;
  float8 cy = ez * ax - ex * az;
  float8 cz = ex * ay - ey * ax;
  float8 s = sqrt(cx * cx + cy * cy + cz * cz);
  if (em->order >= 0)
    return select(moment_term8(ax, ay, az, bx, by, bz, cx, cy, cz, s, nx, ny, nz, 0, em, 0),
                  (float8)(0.0f), s <= 0.0f);
  float8 theta = atan2(s, ax * bx + ay * by + az * bz);
  float8 term = theta * (nx * cx + ny * cy + nz * cz) / s;
  return select(term, (float8)(0.0f), s <= 0.0f);
}

/* A face small against its distance from P: each term above is good to a few roundings of
 * itself, but the terms are of the order of the face's angular size ρ (its size over its
 * distance; the switch reads the distance from vertex 0 to vertex m/2 over vertex 0's distance, a
 * square's diagonal in the figures below) and cancel to E, of the order of ρ², so
 * E keeps only about ρ of their relative precision. In each lane where ρ < PN_SMALL_FACE the
 * face's terms are taken relative to its reference vertex (arc_term.cl), which keeps E to a few
 * roundings of itself; in the other lanes the terms above, unchanged, so that a point's E does
 * not depend on the points beside it in its work-item (a work-item of mixed lanes computes
 * both). Measured against
 * the exact integral in double (square panels of 0.025 to 1.6 m, points 30° or more above both
 * horizons, tests/distant_source_test.cpp, with PN_SMALL_FACE 0 and 100): each term alone errs by
 * up to 9.6e-5 of E at ρ below 0.0125, 1.6e-5 at 0.025 to 0.05, 6.8e-6 at 0.05 to 0.1 and 3.1e-6
 * at 0.1 to 0.2; the relative terms by 1.0e-6 at most below 0.2. Both grow with foreshortening:
 * 11.5° above the horizons, each term alone errs by 2.4e-5 at 0.1 to 0.2 and the relative terms
 * by up to 6.8e-6. The relative terms cost more per arc (an fma-accurate cross product, a second
 * square root, the series), so the faces of the common case, a room's ceiling panels seen from its
 * work plane (ρ above 0.1 within 8.5 m of a 0.6 m panel), take the terms above. */
#define PN_SMALL_FACE 0.1f

/* The reference point of a small face (arc_term.cl): its least vertex in x, then y, then z, so
 * that the terms do not depend on which vertex the face lists first. */
inline int face_reference_vertex(PnSourceFace face, const PnSceneTables* tables) {
  int k = 0;
  float4 least = tables->sourceVertices[face.firstVertex].hi;
  for (int i = 1; i < face.vertexCount; ++i) {
    const float4 v = tables->sourceVertices[face.firstVertex + i].hi;
    if (v.x < least.x || (v.x == least.x && (v.y < least.y || (v.y == least.y && v.z < least.z)))) {
      k = i;
      least = v;
    }
  }
  return k;
}

/* The offset of vertex i of a face from its vertex k, from their double-float positions: the
 * same for every point, and good to a rounding of itself however far from P. */
inline float3 vertex_offset(PnSourceFace face, int i, int k, const PnSceneTables* tables) {
  const PnPosition v = tables->sourceVertices[face.firstVertex + i];
  const PnPosition v0 = tables->sourceVertices[face.firstVertex + k];
  return (v.hi.xyz - v0.hi.xyz) + (v.lo.xyz - v0.lo.xyz);
}

/* The switch's squared size of a face: the distance from its vertex 0 to its vertex m/2 (the
 * opposite corner of a rectangle, the opposite vertex of a disk's polygon), from the hi parts: a
 * criterion, not a term. */
inline float face_switch_size2(PnSourceFace face, const PnSceneTables* tables) {
  const float4 d = tables->sourceVertices[face.firstVertex + face.vertexCount / 2].hi -
                   tables->sourceVertices[face.firstVertex].hi;
  return dot(d.xyz, d.xyz);
}

/* The largest squared offset of a face's vertices from its vertex k (PnCentre's reach2). */
inline float face_reach2(PnSourceFace face, int k, const PnSceneTables* tables) {
  float reach2 = 0.0f;
  for (int i = 0; i < face.vertexCount; ++i) {
    const float3 o = vertex_offset(face, i, k, tables);
    reach2 = fmax(reach2, dot(o, o));
  }
  return reach2;
}

/* Whether the face is small against its distance in some lane: face_switch_size2 below
 * PN_SMALL_FACE² times vertex 0's squared distance (x, y, z from P), at one more vertex and three
 * products per lane. If so, *lanes says in which lanes (each lane takes its own form, so that a
 * point's E does not depend on the points beside it in its work-item) and *centre is the face's
 * reference point (vertex *k) from each lane's P, with the face's spread about it. */
inline bool small_face8(const Points8* pts, PnSourceFace face, const PnSceneTables* tables,
                        float8 x, float8 y, float8 z, PnCentre8* centre, int* k_out, int8* lanes) {
  *lanes =
      face_switch_size2(face, tables) < PN_SMALL_FACE * PN_SMALL_FACE * (x * x + y * y + z * z);
  if (!pn_any(*lanes)) return false;
  const int k = face_reference_vertex(face, tables);
  *k_out = k;
  float8 cx, cy, cz;
  pn_from8(tables->sourceVertices[face.firstVertex + k], pts, &cx, &cy, &cz);
  *centre = pn_centre8(cx, cy, cz, (float8)(face_reach2(face, k, tables)));
  return true;
}

/* small_face8 for one point P (p, p_lo: PnPosition), with the same arithmetic, so that the
 * scalar penumbra path switches where the lanes do: whether the face is small against its
 * distance, and if so *centre. */
inline bool small_face1(float3 p, float3 p_lo, PnSourceFace face, const PnSceneTables* tables,
                        PnCentre1* centre, int* k_out) {
  const float3 v0 = pn_from1(tables->sourceVertices[face.firstVertex], p, p_lo);
  if (!(face_switch_size2(face, tables) < PN_SMALL_FACE * PN_SMALL_FACE * pn_dot(v0, v0)))
    return false;
  const int k = face_reference_vertex(face, tables);
  *k_out = k;
  const float3 c = pn_from1(tables->sourceVertices[face.firstVertex + k], p, p_lo);
  *centre = pn_centre1(c.x, c.y, c.z, face_reach2(face, k, tables));
  return true;
}

/* Vertex i of a face: from P, or (a small face) its offset from the reference vertex k. */
inline void face_vertex8(const Points8* pts, PnSourceFace face, int i, int k,
                         const PnSceneTables* tables, const PnCentre8* centre, float8* x, float8* y,
                         float8* z) {
  if (centre) {
    const float3 o = vertex_offset(face, i, k, tables);
    *x = o.x;
    *y = o.y;
    *z = o.z;
  } else {
    pn_from8(tables->sourceVertices[face.firstVertex + i], pts, x, y, z);
  }
}

/* One boundary arc's term: a and b from P (centre null), or offsets from the centre. */
inline float8 contour_term8(const PnCentre8* centre, float8 ax, float8 ay, float8 az, float8 bx,
                            float8 by, float8 bz, float8 nx, float8 ny, float8 nz,
                            const PnEmission* em) {
  return centre ? arc_term8(centre, ax, ay, az, bx, by, bz, nx, ny, nz, em)
                : edge_term8(ax, ay, az, bx, by, bz, nx, ny, nz, em);
}

/* A face's sum of terms. The relative terms of a face seen edge-on (E 0) cancel to their
 * rounding, either side of 0, and a face's E is never negative (tests/degenerate_test.cpp holds
 * E >= 0 at such points): their sum is taken no lower than 0. */
inline float8 small_face_sum8(const PnCentre8* centre, float8 sum) {
  return centre ? fmax(sum, 0.0f) : sum;
}

/* ---------------------------------------------------------------------------------------------
 * Unoccluded face, eight lanes: the face clipped by each lane's horizon plane (Nishita's type
 * B), streamed edge by edge. A convex face leaves the horizon once (exit) and re-enters once
 * (entry); the chord exit → entry lies in the horizon plane and closes the clipped contour. */

/* Where the contour of a face leaves the horizon (exit) and re-enters it (entry), per lane: the
 * horizon chord exit → entry. */
typedef struct {
  float8 exit_x, exit_y, exit_z, entry_x, entry_y, entry_z;
  int8 has_exit, has_entry;
} HorizonChord8;

inline void chord_begin8(HorizonChord8* c) {
  c->exit_x = c->exit_y = c->exit_z = c->entry_x = c->entry_y = c->entry_z = 0.0f;
  c->has_exit = c->has_entry = 0;
}

/* An edge from a (above the horizon in the lanes of a_in) to b (b_in), which crosses the horizon
 * at (x, y, z) in the lanes where exactly one end is above it. */
inline void chord_track8(HorizonChord8* c, int8 a_in, int8 b_in, float8 x, float8 y, float8 z) {
  int8 leaves = a_in & ~b_in, enters = ~a_in & b_in;
  c->exit_x = select(c->exit_x, x, leaves);
  c->exit_y = select(c->exit_y, y, leaves);
  c->exit_z = select(c->exit_z, z, leaves);
  c->entry_x = select(c->entry_x, x, enters);
  c->entry_y = select(c->entry_y, y, enters);
  c->entry_z = select(c->entry_z, z, enters);
  c->has_exit |= leaves;
  c->has_entry |= enters;
}

/* The lanes whose horizon cuts the face: those with a chord. */
inline int8 chord_cut8(const HorizonChord8* c) {
  return c->has_exit & c->has_entry;
}

/* The sum over the clipped contour, whose points are vectors from P or (centre not null) offsets
 * from the centre, the chord's ends too; with `planar` (not null, centre null) each term by the
 * planar form, whose edges' Δψ it sums. */
typedef struct {
  PnSum8 sum;
  HorizonChord8 chord;
  const PnCentre8* centre;
  float8 centre_height; /* the centre's height above the horizon, or 0 */
  const PnEmission* em; /* how the face emits */
  PnPlanarFrame8* planar;
} HorizonSum8;

/* One arc's term in the sum's form, in the lanes of `use`. */
inline void horizon_add8(HorizonSum8* h, float8 ax, float8 ay, float8 az, float8 bx, float8 by,
                         float8 bz, float8 nx, float8 ny, float8 nz, int8 use) {
  float8 term;
  if (h->planar) {
    float8 dpsi;
    term = planar_term8(ax, ay, az, bx, by, bz, h->planar, nx, ny, nz, h->em, &dpsi);
    h->planar->dpsi_sum += select((float8)(0.0f), dpsi, use);
  } else {
    term = contour_term8(h->centre, ax, ay, az, bx, by, bz, nx, ny, nz, h->em);
  }
  pn_sum_add8(&h->sum, select((float8)(0.0f), term, use));
}

inline void horizon_begin8(HorizonSum8* h, const PnCentre8* centre, float8 nx, float8 ny, float8 nz,
                           const PnEmission* em) {
  h->planar = 0;
  h->centre = centre;
  h->centre_height = centre ? nx * centre->x + ny * centre->y + nz * centre->z : 0.0f;
  h->em = em;
  h->sum.s = h->sum.c = 0.0f;
  chord_begin8(&h->chord);
}

/* One edge a → b of the face (vectors from P), ha and hb their heights above the horizon. */
inline void horizon_edge8(HorizonSum8* h, float8 ax, float8 ay, float8 az, float8 ha, float8 bx,
                          float8 by, float8 bz, float8 hb, float8 nx, float8 ny, float8 nz) {
  int8 a_in = ha >= 0.0f, b_in = hb >= 0.0f;
  float8 t = ha / (ha - hb); /* used only where exactly one end is above the horizon */
  float8 cx = ax + t * (bx - ax), cy = ay + t * (by - ay), cz = az + t * (bz - az);
  horizon_add8(h, select(cx, ax, a_in), select(cy, ay, a_in), select(cz, az, a_in),
               select(cx, bx, b_in), select(cy, by, b_in), select(cz, bz, b_in), nx, ny, nz,
               a_in | b_in);
  chord_track8(&h->chord, a_in, b_in, cx, cy, cz);
}

/* horizon_edge8 from the current vertex a, at height ha, to b; b becomes the current vertex. */
inline void horizon_next8(HorizonSum8* h, float8* ax, float8* ay, float8* az, float8* ha, float8 bx,
                          float8 by, float8 bz, float8 nx, float8 ny, float8 nz) {
  float8 hb =
      h->centre ? h->centre_height + (nx * bx + ny * by + nz * bz) : nx * bx + ny * by + nz * bz;
  horizon_edge8(h, *ax, *ay, *az, *ha, bx, by, bz, hb, nx, ny, nz);
  *ax = bx;
  *ay = by;
  *az = bz;
  *ha = hb;
}

inline float8 horizon_end8(HorizonSum8* h, float8 nx, float8 ny, float8 nz) {
  const HorizonChord8* c = &h->chord;
  int8 cut = chord_cut8(c);
  if (pn_any(cut)) /* most lanes see whole faces: skip the chord's atan2 when none is cut */
    horizon_add8(h, c->exit_x, c->exit_y, c->exit_z, c->entry_x, c->entry_y, c->entry_z, nx, ny, nz,
                 cut);
  if (!h->planar) return h->sum.s + h->sum.c;
  /* An unoccluded face's E is never negative; its rounding near the face's plane may be. */
  return fmax((h->sum.s + h->sum.c) + planar_closing8(h->planar, h->em), 0.0f);
}

/* whole_face8 for a small face (small_face8): its terms relative to its reference vertex k. */
inline float8 whole_small_face8(const Points8* pts, PnSourceFace face, int k,
                                const PnCentre8* centre, const PnSceneTables* tables,
                                const PnEmission* em) {
  const int m = face.vertexCount;
  float3 a = vertex_offset(face, 0, k, tables);
  PnSum8 sum = {0.0f, 0.0f};
  for (int i = 0; i < m; ++i) {
    const float3 b = vertex_offset(face, i + 1 == m ? 0 : i + 1, k, tables);
    pn_sum_add8(&sum,
                arc_term8(centre, a.x, a.y, a.z, b.x, b.y, b.z, pts->nx, pts->ny, pts->nz, em));
    a = b;
  }
  return select((float8)(0.0f), small_face_sum8(centre, sum.s + sum.c),
                in_front8(face, pts->px, pts->py, pts->pz));
}

/* Whether some lane's horizon cuts the face: a vertex (from P) below the horizon plane. */
inline int8 below_horizon8(const Points8* pts, float8 ax, float8 ay, float8 az) {
  return pts->nx * ax + pts->ny * ay + pts->nz * az < 0.0f;
}

/* The same sum where no lane's horizon cuts the face (every vertex at height >= 0): the face's
 * own edges, no clipping; the same sum unoccluded_face8 gives there. The horizon test is taken
 * on the vertices as the loop reads them; where it finds a cut, *cut is set and the caller takes
 * unoccluded_face8 instead (the value returned is then meaningless). */
inline float8 whole_face8(const Points8* pts, PnSourceFace face, const PnSceneTables* tables,
                          bool* cut) {
  const float8 nx = pts->nx, ny = pts->ny, nz = pts->nz;
  const int m = face.vertexCount;
  const PnEmission em = emission_of(face, tables);
  float8 ax, ay, az, bx, by, bz;
  pn_from8(tables->sourceVertices[face.firstVertex], pts, &ax, &ay, &az);
  int8 below = below_horizon8(pts, ax, ay, az);
  PnCentre8 centre;
  int k = 0;
  int8 small_lanes = 0;
  const bool any_small = small_face8(pts, face, tables, ax, ay, az, &centre, &k, &small_lanes);
  if (pn_any(planar_lanes8(face, &em, ax, ay, az, false) & ~small_lanes)) {
    *cut = true; /* unoccluded_face8 takes the planar form where it serves */
    return 0.0f;
  }
  if (any_small && pn_all(small_lanes)) {
    for (int i = 1; i < m; ++i) {
      pn_from8(tables->sourceVertices[face.firstVertex + i], pts, &bx, &by, &bz);
      below |= below_horizon8(pts, bx, by, bz);
    }
    *cut = pn_any(below);
    return *cut ? 0.0f : whole_small_face8(pts, face, k, &centre, tables, &em);
  }
  PnSum8 sum = {0.0f, 0.0f};
  for (int i = 0; i < m; ++i) {
    pn_from8(tables->sourceVertices[face.firstVertex + (i + 1 == m ? 0 : i + 1)], pts, &bx, &by,
             &bz);
    if (i + 1 < m) below |= below_horizon8(pts, bx, by, bz);
    pn_sum_add8(&sum, edge_term8(ax, ay, az, bx, by, bz, nx, ny, nz, &em));
    ax = bx;
    ay = by;
    az = bz;
  }
  *cut = pn_any(below);
  if (*cut) return 0.0f;
  const float8 e =
      select((float8)(0.0f), sum.s + sum.c, in_front8(face, pts->px, pts->py, pts->pz));
  if (!any_small) return e;
  return select(e, whole_small_face8(pts, face, k, &centre, tables, &em), small_lanes);
}

/* unoccluded_face8's sum with each term taken from P (centre null) or relative to the small
 * face's reference vertex k, or (planar not null, centre null) by the planar form. */
inline float8 horizon_face8(const Points8* pts, PnSourceFace face, const PnSceneTables* tables,
                            const PnCentre8* centre, int k, const PnEmission* em,
                            PnPlanarFrame8* planar) {
  const float8 nx = pts->nx, ny = pts->ny, nz = pts->nz;
  float8 ax, ay, az, bx, by, bz;
  HorizonSum8 h;
  horizon_begin8(&h, centre, nx, ny, nz, em);
  h.planar = planar;
  const int m = face.vertexCount;
  face_vertex8(pts, face, 0, k, tables, centre, &ax, &ay, &az);
  float8 ha =
      centre ? h.centre_height + (nx * ax + ny * ay + nz * az) : nx * ax + ny * ay + nz * az;
  for (int i = 0; i < m; ++i) {
    face_vertex8(pts, face, i + 1 == m ? 0 : i + 1, k, tables, centre, &bx, &by, &bz);
    horizon_next8(&h, &ax, &ay, &az, &ha, bx, by, bz, nx, ny, nz);
  }
  const float8 sum = small_face_sum8(centre, horizon_end8(&h, nx, ny, nz));
  return select((float8)(0.0f), sum, in_front8(face, pts->px, pts->py, pts->pz));
}

/* The face's lanes that are not small against their distance: the planar form in the lanes
 * that see it near its plane, Lambert's (or the moment) terms from P in the others. */
inline float8 large_face8(const Points8* pts, PnSourceFace face, const PnSceneTables* tables,
                          const PnEmission* em, int8 planar) {
  if (!pn_any(planar)) return horizon_face8(pts, face, tables, 0, 0, em, 0);
  PnPlanarFrame8 frame = planar_frame8(pts, face, tables);
  const float8 e_planar = horizon_face8(pts, face, tables, 0, 0, em, &frame);
  if (pn_all(planar)) return e_planar;
  return select(horizon_face8(pts, face, tables, 0, 0, em, 0), e_planar, planar);
}

inline float8 unoccluded_face8(const Points8* pts, PnSourceFace face, const PnSceneTables* tables) {
  const PnEmission em = emission_of(face, tables);
  PnCentre8 small;
  int k = 0;
  int8 small_lanes = 0;
  float8 ax, ay, az;
  pn_from8(tables->sourceVertices[face.firstVertex], pts, &ax, &ay, &az);
  const int8 planar = planar_lanes8(face, &em, ax, ay, az, false);
  if (!small_face8(pts, face, tables, ax, ay, az, &small, &k, &small_lanes))
    return large_face8(pts, face, tables, &em, planar);
  const float8 e_small = horizon_face8(pts, face, tables, &small, k, &em, 0);
  if (pn_all(small_lanes)) return e_small;
  return select(large_face8(pts, face, tables, &em, planar & ~small_lanes), e_small, small_lanes);
}
