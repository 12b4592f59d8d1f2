/* Lambert's contour integral for an unoccluded face (Nishita & Nakamae, §2.5; docs/method.md).
 *
 * For a point P with unit normal n and the visible part R of a source face of luminance L,
 * Lambert's contour integral gives  E = (L/2) · Σ θ_i · n·unit(b_i × a_i)  over the boundary
 * edges (a_i → b_i) of R (vectors from P) oriented with R on their left as seen from P, where
 * θ_i = atan2(|a_i × b_i|, a_i·b_i). Only directions matter, so every edge is integrated on the
 * 3-D segment it comes from: a source edge, the horizon chord, or an occluder's contour edge.
 * Here: one edge's term in eight lanes, and the face clipped by each lane's horizon. */

#include "prelude.cl"

/* cross(b, a) is computed as cross(b − a, a): for a short edge far from P, a and b are long and
 * nearly parallel, b − a is exact in float (Sterbenz) and short, and the products are |e|·|a|
 * instead of |a|·|b|. For a 0.6 m panel 10 m away this takes the term's relative error from
 * about 2e-6 to 1e-7, which matters because the terms of a distant source nearly cancel. (The
 * penumbra paths integrate pieces of edges with piece_term, which keeps this accuracy for ends
 * that are not vertices.) A zero-length edge, or one whose line passes through P, spans no solid
 * angle. */
inline float8 edge_term8(float8 ax, float8 ay, float8 az, float8 bx, float8 by, float8 bz,
                         float8 nx, float8 ny, float8 nz) {
  float8 ex = bx - ax, ey = by - ay, ez = bz - az;
  float8 cx = ey * az - ez * ay;
  float8 cy = ez * ax - ex * az;
  float8 cz = ex * ay - ey * ax;
  float8 s = sqrt(cx * cx + cy * cy + cz * cz);
  float8 theta = atan2(s, ax * bx + ay * by + az * bz);
  float8 term = theta * (nx * cx + ny * cy + nz * cz) / s;
  return select(term, (float8)(0.0f), s <= 0.0f);
}

/* ---------------------------------------------------------------------------------------------
 * Unoccluded face, eight lanes: the face clipped by each lane's horizon plane (Nishita's type
 * B), streamed edge by edge. A convex face leaves the horizon once (exit) and re-enters once
 * (entry); the chord exit → entry lies in the horizon plane and closes the clipped contour. */

typedef struct {
  PnSum8 sum;
  float8 exx, exy, exz, enx, eny, enz; /* where the contour leaves / re-enters the horizon */
  int8 has_exit, has_entry;
} HorizonSum8;

inline void horizon_begin8(HorizonSum8* h) {
  h->sum.s = h->sum.c = 0.0f;
  h->exx = h->exy = h->exz = h->enx = h->eny = h->enz = 0.0f;
  h->has_exit = h->has_entry = 0;
}

/* One edge a → b of the face (vectors from P), ha and hb their heights above the horizon. */
inline void horizon_edge8(HorizonSum8* h, float8 ax, float8 ay, float8 az, float8 ha, float8 bx,
                          float8 by, float8 bz, float8 hb, float8 nx, float8 ny, float8 nz) {
  int8 a_in = ha >= 0.0f, b_in = hb >= 0.0f;
  float8 t = ha / (ha - hb); /* used only where exactly one end is above the horizon */
  float8 cx = ax + t * (bx - ax), cy = ay + t * (by - ay), cz = az + t * (bz - az);
  float8 term =
      edge_term8(select(cx, ax, a_in), select(cy, ay, a_in), select(cz, az, a_in),
                 select(cx, bx, b_in), select(cy, by, b_in), select(cz, bz, b_in), nx, ny, nz);
  pn_sum_add8(&h->sum, select((float8)(0.0f), term, a_in | b_in));
  int8 leaves = a_in & ~b_in, enters = ~a_in & b_in;
  h->exx = select(h->exx, cx, leaves);
  h->exy = select(h->exy, cy, leaves);
  h->exz = select(h->exz, cz, leaves);
  h->enx = select(h->enx, cx, enters);
  h->eny = select(h->eny, cy, enters);
  h->enz = select(h->enz, cz, enters);
  h->has_exit |= leaves;
  h->has_entry |= enters;
}

inline float8 horizon_end8(HorizonSum8* h, float8 nx, float8 ny, float8 nz) {
  int8 cut = h->has_exit & h->has_entry;
  if (pn_any(cut)) /* most lanes see whole faces: skip the chord's atan2 when none is cut */
    pn_sum_add8(
        &h->sum,
        select((float8)(0.0f),
               edge_term8(h->exx, h->exy, h->exz, h->enx, h->eny, h->enz, nx, ny, nz), cut));
  return h->sum.s + h->sum.c;
}

/* The same where no lane's horizon cuts the face (every vertex at height >= 0, as
 * horizon_edge8 tests them): the face's own edges, no clipping; the same sum unoccluded_face8
 * gives there. */
inline float8 whole_face8(float8 px, float8 py, float8 pz, float8 nx, float8 ny, float8 nz,
                          PnSourceFace face, const PnSceneTables* tables) {
  const int m = face.vertexCount;
  float4 q = tables->sourceVertices[face.firstVertex];
  float8 ax = q.x - px, ay = q.y - py, az = q.z - pz;
  PnSum8 sum = {0.0f, 0.0f};
  for (int i = 0; i < m; ++i) {
    q = tables->sourceVertices[face.firstVertex + (i + 1 == m ? 0 : i + 1)];
    float8 bx = q.x - px, by = q.y - py, bz = q.z - pz;
    pn_sum_add8(&sum, edge_term8(ax, ay, az, bx, by, bz, nx, ny, nz));
    ax = bx;
    ay = by;
    az = bz;
  }
  float8 front = face.plane.x * px + face.plane.y * py + face.plane.z * pz - face.plane.w;
  return select((float8)(0.0f), sum.s + sum.c, front > 0.0f);
}

inline bool horizon_cuts8(float8 px, float8 py, float8 pz, float8 nx, float8 ny, float8 nz,
                          PnSourceFace face, const PnSceneTables* tables) {
  int8 below = 0;
  for (int i = 0; i < face.vertexCount; ++i) {
    float4 q = tables->sourceVertices[face.firstVertex + i];
    float8 ax = q.x - px, ay = q.y - py, az = q.z - pz;
    below |= nx * ax + ny * ay + nz * az < 0.0f;
  }
  return pn_any(below);
}

inline float8 unoccluded_face8(float8 px, float8 py, float8 pz, float8 nx, float8 ny, float8 nz,
                               PnSourceFace face, const PnSceneTables* tables) {
  HorizonSum8 h;
  horizon_begin8(&h);
  const int m = face.vertexCount;
  float4 q = tables->sourceVertices[face.firstVertex];
  float8 ax = q.x - px, ay = q.y - py, az = q.z - pz;
  float8 ha = nx * ax + ny * ay + nz * az;
  for (int i = 0; i < m; ++i) {
    q = tables->sourceVertices[face.firstVertex + (i + 1 == m ? 0 : i + 1)];
    float8 bx = q.x - px, by = q.y - py, bz = q.z - pz;
    float8 hb = nx * bx + ny * by + nz * bz;
    horizon_edge8(&h, ax, ay, az, ha, bx, by, bz, hb, nx, ny, nz);
    ax = bx;
    ay = by;
    az = bz;
    ha = hb;
  }
  float8 sum = horizon_end8(&h, nx, ny, nz);
  /* Only points strictly in front of the face see it. */
  float8 front = face.plane.x * px + face.plane.y * py + face.plane.z * pz - face.plane.w;
  return select((float8)(0.0f), sum, front > 0.0f);
}
