/* Lambert's contour integral for an unoccluded face (Nishita & Nakamae, §2.5; docs/method.md).
 *
 * For a point P with unit normal n and the visible part R of a source face of luminance L,
 * Lambert's contour integral gives  E = (L/2) · Σ θ_i · n·unit(b_i × a_i)  over the boundary
 * edges (a_i → b_i) of R (vectors from P) oriented with R on their left as seen from P, where
 * θ_i = atan2(|a_i × b_i|, a_i·b_i). Only directions matter, so every edge is integrated on the
 * 3-D segment it comes from: a source edge, the horizon chord, or an occluder's contour edge.
 * Here: one edge's term in eight lanes, and the face clipped by each lane's horizon. */

#include "luminance_moments.cl"

/* cross(b, a) is computed as cross(b − a, a): for a short edge far from P, a and b are long and
 * nearly parallel, b − a is exact in float (Sterbenz) and short, and the products are |e|·|a|
 * instead of |a|·|b|. For a 0.6 m panel 10 m away this takes the term's relative error from
 * about 2e-6 to 1e-7, which matters because the terms of a distant source nearly cancel. (The
 * penumbra paths integrate pieces of edges with piece_term, which keeps this accuracy for ends
 * that are not vertices.) A zero-length edge, or one whose line passes through P, spans no solid
 * angle. A face of polynomial luminance takes the moment term (luminance_moments.cl) on the same
 * cross product. */
inline float8 edge_term8(float8 ax, float8 ay, float8 az, float8 bx, float8 by, float8 bz,
                         float8 nx, float8 ny, float8 nz, const PnEmission* em) {
  float8 ex = bx - ax, ey = by - ay, ez = bz - az;
  float8 cx = ey * az - ez * ay;
  float8 cy = ez * ax - ex * az;
  float8 cz = ex * ay - ey * ax;
  float8 s = sqrt(cx * cx + cy * cy + cz * cz);
  if (em->order >= 0)
    return select(moment_term8(ax, ay, az, bx, by, bz, cx, cy, cz, s, nx, ny, nz, em),
                  (float8)(0.0f), s <= 0.0f);
  float8 theta = atan2(s, ax * bx + ay * by + az * bz);
  float8 term = theta * (nx * cx + ny * cy + nz * cz) / s;
  return select(term, (float8)(0.0f), s <= 0.0f);
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

typedef struct {
  PnSum8 sum;
  HorizonChord8 chord;
  const PnEmission* em; /* how the face emits */
} HorizonSum8;

inline void horizon_begin8(HorizonSum8* h, const PnEmission* em) {
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
  float8 term = edge_term8(select(cx, ax, a_in), select(cy, ay, a_in), select(cz, az, a_in),
                           select(cx, bx, b_in), select(cy, by, b_in), select(cz, bz, b_in), nx, ny,
                           nz, h->em);
  pn_sum_add8(&h->sum, select((float8)(0.0f), term, a_in | b_in));
  chord_track8(&h->chord, a_in, b_in, cx, cy, cz);
}

/* horizon_edge8 from the current vertex a, at height ha, to b; b becomes the current vertex. */
inline void horizon_next8(HorizonSum8* h, float8* ax, float8* ay, float8* az, float8* ha, float8 bx,
                          float8 by, float8 bz, float8 nx, float8 ny, float8 nz) {
  float8 hb = nx * bx + ny * by + nz * bz;
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
    pn_sum_add8(&h->sum, select((float8)(0.0f),
                                edge_term8(c->exit_x, c->exit_y, c->exit_z, c->entry_x, c->entry_y,
                                           c->entry_z, nx, ny, nz, h->em),
                                cut));
  return h->sum.s + h->sum.c;
}

/* The same where no lane's horizon cuts the face (every vertex at height >= 0, as
 * horizon_edge8 tests them): the face's own edges, no clipping; the same sum unoccluded_face8
 * gives there. */
inline float8 whole_face8(const Points8* pts, PnSourceFace face, const PnSceneTables* tables) {
  const float8 nx = pts->nx, ny = pts->ny, nz = pts->nz;
  const int m = face.vertexCount;
  const PnEmission em = emission_of(face, tables);
  float8 ax, ay, az, bx, by, bz;
  pn_from8(tables->sourceVertices[face.firstVertex], pts, &ax, &ay, &az);
  PnSum8 sum = {0.0f, 0.0f};
  for (int i = 0; i < m; ++i) {
    pn_from8(tables->sourceVertices[face.firstVertex + (i + 1 == m ? 0 : i + 1)], pts, &bx, &by,
             &bz);
    pn_sum_add8(&sum, edge_term8(ax, ay, az, bx, by, bz, nx, ny, nz, &em));
    ax = bx;
    ay = by;
    az = bz;
  }
  return select((float8)(0.0f), sum.s + sum.c, in_front8(face, pts->px, pts->py, pts->pz));
}

inline bool horizon_cuts8(const Points8* pts, PnSourceFace face, const PnSceneTables* tables) {
  int8 below = 0;
  for (int i = 0; i < face.vertexCount; ++i) {
    float8 ax, ay, az;
    pn_from8(tables->sourceVertices[face.firstVertex + i], pts, &ax, &ay, &az);
    below |= pts->nx * ax + pts->ny * ay + pts->nz * az < 0.0f;
  }
  return pn_any(below);
}

inline float8 unoccluded_face8(const Points8* pts, PnSourceFace face, const PnSceneTables* tables) {
  const float8 nx = pts->nx, ny = pts->ny, nz = pts->nz;
  const PnEmission em = emission_of(face, tables);
  HorizonSum8 h;
  horizon_begin8(&h, &em);
  const int m = face.vertexCount;
  float8 ax, ay, az, bx, by, bz;
  pn_from8(tables->sourceVertices[face.firstVertex], pts, &ax, &ay, &az);
  float8 ha = nx * ax + ny * ay + nz * az;
  for (int i = 0; i < m; ++i) {
    pn_from8(tables->sourceVertices[face.firstVertex + (i + 1 == m ? 0 : i + 1)], pts, &bx, &by,
             &bz);
    horizon_next8(&h, &ax, &ay, &az, &ha, bx, by, bz, nx, ny, nz);
  }
  float8 sum = horizon_end8(&h, nx, ny, nz);
  return select((float8)(0.0f), sum, in_front8(face, pts->px, pts->py, pts->pz));
}
