/* Exact direct illuminance at sample points from Lambertian convex sources, with occlusion by
 * convex polyhedra (Nishita & Nakamae, §2.5; DESIGN.md "The lighting method").
 *
 * For a point P with unit normal n and the visible part R of a source face of luminance L,
 * Lambert's contour integral gives  E = (L/2) · Σ θ_i · n·unit(b_i × a_i)  over the boundary
 * edges (a_i → b_i) of R (vectors from P) oriented with R on their left as seen from P, where
 * θ_i = atan2(|a_i × b_i|, a_i·b_i). Only directions matter, so every edge is integrated on the
 * 3-D segment it comes from: a source edge, the horizon chord, or an occluder's contour edge.
 *
 * Work layout: one work-item computes PN_LANES (8) consecutive points, one per float8 lane,
 * because PoCL does not vectorise atan2 across work-items (STACK.md: explicit lanes are 5×
 * faster). Lanes whose view of a face may be shaded take the scalar penumbra path.
 *
 * Build options from the host: -DPN_EPS_REL=<Tolerance::kKernelRelative>. */

#ifndef PN_EPS_REL
#error "the host passes -DPN_EPS_REL"
#endif

/* Whether any lane of a mask (lanes all ones or all zeros, as comparisons give) is set. PoCL's
 * any() extracts the eight lanes one by one; a vector OR-reduction compiles to one vptest. */
inline bool pn_any(int8 m) {
  return __builtin_reduce_or(m) != 0;
}

/* Compensated sums (Knuth's TwoSum: s + c carries the sum to about twice float precision). A
 * contour's terms are large and cancel: a window 7 m away past a column gives terms of 0.29 that
 * sum to 0.015, and each rounding of a running sum of such terms is as large as the rest of the
 * error. TwoSum, not Kahan, because a term may be larger than the sum so far. Safe as written:
 * OpenCL C reassociates nothing unless built with -cl-unsafe-math-optimizations (the host does
 * not), and there is no product here to contract into an fma. Every sum of terms and of faces
 * uses it (culling_test: the default and plain paths went from 1.25e-6 to 8.8e-7 of
 * E_unoccluded apart on the open office, for 1.6 % more kernel instructions). */
#define PN_DEFINE_SUM(T, Sum, add)        \
  typedef struct {                        \
    T s, c;                               \
  } Sum;                                  \
  inline void add(Sum* a, T x) {          \
    T t = a->s + x, bp = t - a->s;        \
    a->c += (a->s - (t - bp)) + (x - bp); \
    a->s = t;                             \
  }
PN_DEFINE_SUM(float, PnSum, pn_sum_add)    /* one body for the scalar path */
PN_DEFINE_SUM(float8, PnSum8, pn_sum_add8) /* and for eight lanes */
#undef PN_DEFINE_SUM

/* ---------------------------------------------------------------------------------------------
 * Lambert's term of one edge, scalar and in eight lanes. a, b are vectors from P. */

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
                          PnSourceFace face, __global const float4* vertices) {
  const int m = face.vertexCount;
  float4 q = vertices[face.firstVertex];
  float8 ax = q.x - px, ay = q.y - py, az = q.z - pz;
  PnSum8 sum = {0.0f, 0.0f};
  for (int i = 0; i < m; ++i) {
    q = vertices[face.firstVertex + (i + 1 == m ? 0 : i + 1)];
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
                          PnSourceFace face, __global const float4* vertices) {
  int8 below = 0;
  for (int i = 0; i < face.vertexCount; ++i) {
    float4 q = vertices[face.firstVertex + i];
    float8 ax = q.x - px, ay = q.y - py, az = q.z - pz;
    below |= nx * ax + ny * ay + nz * az < 0.0f;
  }
  return pn_any(below);
}

inline float8 unoccluded_face8(float8 px, float8 py, float8 pz, float8 nx, float8 ny, float8 nz,
                               PnSourceFace face, __global const float4* vertices) {
  HorizonSum8 h;
  horizon_begin8(&h);
  const int m = face.vertexCount;
  float4 q = vertices[face.firstVertex];
  float8 ax = q.x - px, ay = q.y - py, az = q.z - pz;
  float8 ha = nx * ax + ny * ay + nz * az;
  for (int i = 0; i < m; ++i) {
    q = vertices[face.firstVertex + (i + 1 == m ? 0 : i + 1)];
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

/* ---------------------------------------------------------------------------------------------
 * Apertures (host/shadow/aperture.hpp). For the lanes that use the aperture: the visible part of
 * the face, face ∩ cone(P, A), as a rectangle relative to P. A projects from P onto the face's
 * plane by the homothety of ratio k = hS / hA about P (hS, hA: P's heights above the face's
 * and A's planes), so the rectangle is the min/max of two rectangles. Empty (u1 <= u0 or
 * v1 <= v0): the wall hides the whole face. */

typedef struct {
  int8 use;              /* lanes strictly in front of A and inside the room's box */
  float8 u0, u1, v0, v1; /* the visible rectangle, coordinates relative to P's */
  float8 depth;          /* the face's plane relative to P along the emission direction */
} ApertureView8;

inline ApertureView8 aperture_view8(float8 px, float8 py, float8 pz, PnSourceFace face,
                                    PnAperture ap, float eps_length) {
  ApertureView8 v;
  float8 ha = ap.plane.x * px + ap.plane.y * py + ap.plane.z * pz - ap.plane.w;
  float8 hs = face.plane.x * px + face.plane.y * py + face.plane.z * pz - face.plane.w;
  v.use = (ha > eps_length) & (px >= ap.roomLo.x) & (px <= ap.roomHi.x) & (py >= ap.roomLo.y) &
          (py <= ap.roomHi.y) & (pz >= ap.roomLo.z) & (pz <= ap.roomHi.z);
  float8 pu = ap.axisU.x * px + ap.axisU.y * py + ap.axisU.z * pz;
  float8 pv = ap.axisV.x * px + ap.axisV.y * py + ap.axisV.z * pz;
  /* A's side at offset d from P lands at k·d = d + d·(t / hA) on the face's plane (t = hS − hA,
   * the wall's thickness): the large part d keeps the one rounding of a vertex difference, as
   * the face's own sides do; k·d rounds relative to d, 1e-6 of the window at 10 m. */
  float8 g = ap.thickness.x / ha;
  float8 du0 = ap.openingRect.x - pu, du1 = ap.openingRect.y - pu;
  float8 dv0 = ap.openingRect.z - pv, dv1 = ap.openingRect.w - pv;
  v.u0 = fmax(ap.sourceRect.x - pu, du0 + du0 * g);
  v.u1 = fmin(ap.sourceRect.y - pu, du1 + du1 * g);
  v.v0 = fmax(ap.sourceRect.z - pv, dv0 + dv0 * g);
  v.v1 = fmin(ap.sourceRect.w - pv, dv1 + dv1 * g);
  v.depth = -hs;
  return v;
}

/* Corner i (0..3, counter-clockwise about the emission direction) of the visible rectangle,
 * relative to P. */
inline void aperture_corner8(ApertureView8 v, PnAperture ap, float4 n, int i, float8* x, float8* y,
                             float8* z) {
  float8 u = (i == 0 || i == 3) ? v.u0 : v.u1;
  float8 w = (i < 2) ? v.v0 : v.v1;
  *x = u * ap.axisU.x + w * ap.axisV.x + v.depth * n.x;
  *y = u * ap.axisU.y + w * ap.axisV.y + v.depth * n.y;
  *z = u * ap.axisU.z + w * ap.axisV.z + v.depth * n.z;
}

inline float8 unoccluded_aperture8(ApertureView8 v, PnAperture ap, float4 plane, float8 nx,
                                   float8 ny, float8 nz) {
  HorizonSum8 h;
  horizon_begin8(&h);
  float8 ax, ay, az;
  aperture_corner8(v, ap, plane, 0, &ax, &ay, &az);
  float8 ha = nx * ax + ny * ay + nz * az;
  for (int i = 0; i < 4; ++i) {
    float8 bx, by, bz;
    aperture_corner8(v, ap, plane, (i + 1) & 3, &bx, &by, &bz);
    float8 hb = nx * bx + ny * by + nz * bz;
    horizon_edge8(&h, ax, ay, az, ha, bx, by, bz, hb, nx, ny, nz);
    ax = bx;
    ay = by;
    az = bz;
    ha = hb;
  }
  return horizon_end8(&h, nx, ny, nz);
}

/* Lanes for which the occluder cannot meet conv(P, visible rectangle): all its vertices lie
 * outside one side plane of that pyramid, by more than eps_length across at their depth. A
 * point x (from P) at depth h towards the face is inside iff u0·h <= x·axisU·hS <= u1·h (and
 * the same in v), hS the face's depth. */
inline int8 misses_aperture_view8(float8 px, float8 py, float8 pz, ApertureView8 v, PnAperture ap,
                                  float4 n, PnOccluder o, __global const float4* overts,
                                  float eps_length) {
  float8 hs = -v.depth, margin = eps_length * hs;
  int8 u0 = -1, u1 = -1, v0 = -1, v1 = -1;
  for (int k = 0; k < o.vertexCount; ++k) {
    float4 q = overts[o.firstVertex + k];
    float8 dx = q.x - px, dy = q.y - py, dz = q.z - pz;
    float8 xu = (ap.axisU.x * dx + ap.axisU.y * dy + ap.axisU.z * dz) * hs;
    float8 xv = (ap.axisV.x * dx + ap.axisV.y * dy + ap.axisV.z * dz) * hs;
    float8 h = -(n.x * dx + n.y * dy + n.z * dz);
    u0 &= xu < v.u0 * h - margin;
    u1 &= xu > v.u1 * h + margin;
    v0 &= xv < v.v0 * h - margin;
    v1 &= xv > v.v1 * h + margin;
    if (!pn_any(u0 | u1 | v0 | v1)) break;
  }
  return u0 | u1 | v0 | v1;
}

/* ---------------------------------------------------------------------------------------------
 * Occluder culling shared by both paths. An occluder cannot shade P from the face when
 *  - P lies on it (the solid P belongs to), or
 *  - one of its separating planes (faces whose closed outside holds the whole source face) has
 *    P in its closed outside too: every segment P→source then stays in that half-space, or
 *  - it misses the pyramid P + cone(S'), S' the visible part of the face before occlusion:
 *    its bounding sphere outside one side plane or wholly below the horizon, or (through an
 *    aperture) all its vertices outside one side plane (outside_source_pyramid). */

inline bool occluder_separated(float3 p, PnOccluder o, __global const float4* planes,
                               float eps_length) {
  for (int j = 0; j < o.separatingCount; ++j) {
    float4 pl = planes[o.firstSeparating + j];
    if (dot(pl.xyz, p) - pl.w >= -eps_length) return true;
  }
  return false;
}

/* The shadow volumes of an occluder for this face (host/shadow/shadow_volume.hpp): inside the
 * penumbra volume grown by eps the occluder may shade P; deeper than eps inside the umbra
 * volume it hides the whole face. Both err on the safe side (the exact path decides). */
inline bool in_penumbra_volume(float3 p, PnOccluder o, __global const float4* planes,
                               float eps_length) {
  for (int j = 0; j < o.penumbraCount; ++j) {
    float4 pl = planes[o.firstPenumbra + j];
    if (dot(pl.xyz, p) - pl.w > eps_length) return false;
  }
  return true;
}

/* The occluders a patch considers for one face: its candidate list, or (count < 0, the plain
 * path) every occluder of the face. */
inline int occluder_count(PnPatchFace pf, PnSourceFace face) {
  return pf.candidateCount < 0 ? face.occluderCount : pf.candidateCount;
}
inline int occluder_index(int i, PnPatchFace pf, PnSourceFace face,
                          __global const int* candidates) {
  return pf.candidateCount < 0 ? face.firstOccluder + i : candidates[pf.firstCandidate + i];
}

/* ---------------------------------------------------------------------------------------------
 * The penumbra path for one point (Nishita §2.5(2), DESIGN.md step 4): the visible region is
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
 * a source edge never leaks. */

/* S' vertices, relative to P: each clip by a plane through P adds at most one vertex (the
 * horizon, a contact's face, a wedge piece's faces). */
#define PN_MAX_SOURCE_POLYGON \
  (PN_MAX_SOURCE_VERTICES + 1 + PN_MAX_CONTACTS + PN_MAX_WEDGES * PN_MAX_WEDGE_FACES)

typedef struct {
  float3 sv[PN_MAX_SOURCE_POLYGON];
  float3 sm[PN_MAX_SOURCE_POLYGON]; /* unit side normals of S' */
  int ns;
  /* The active occluders' contour edges, hole-oriented, relative to P, with their unit side-plane
   * normals along cross(a, b) (zero where P is on the edge's line: no plane), extracted once per
   * point: occluder v owns edges [first_contour[v], first_contour[v + 1]). */
  float3 ca[PN_MAX_CONTOUR_EDGES], cb[PN_MAX_CONTOUR_EDGES], cm[PN_MAX_CONTOUR_EDGES];
  int first_contour[PN_MAX_ACTIVE_OCCLUDERS + 1];
  int na;
} PenumbraState;

/* Keeps the part of S' with keep·x >= 0 (a plane through P; Sutherland–Hodgman). */
void clip_source(PenumbraState* st, float3 keep) {
  float3 out[PN_MAX_SOURCE_POLYGON];
  int count = 0;
  float3 a = st->sv[st->ns - 1];
  float ha = dot(keep, a);
  for (int i = 0; i < st->ns; ++i) {
    float3 b = st->sv[i];
    float hb = dot(keep, b);
    if ((ha >= 0.0f) != (hb >= 0.0f)) out[count++] = a + (ha / (ha - hb)) * (b - a);
    if (hb >= 0.0f) out[count++] = b;
    a = b;
    ha = hb;
  }
  for (int i = 0; i < count; ++i) st->sv[i] = out[i];
  st->ns = count;
}

/* A solid P lies on (no face sees P; P is not its own solid) has no contour line from P: the
 * directions into it form the cone {x : f·x < 0 for every face f through P}. Faces whose
 * closed inside already holds all of S' do not limit that cone within S' (the floor under a
 * cabinet: the cabinet's bottom face holds everything above the horizon, so the point is
 * dark). Returns how many faces limit it (-1: no face passes through P, a point strictly
 * inside, which the host flags), the first `capacity` of them in `limiting` and, in `opposed`,
 * the one most opposed to P's normal.
 *  - None: P sees nothing of the source face.
 *  - One: S' is clipped by it, exactly.
 *  - Two or more: P lies on an edge or a corner of the solid (a floor point at a cabinet's
 *    corner, a point on the edge two boxes share) and S' minus the wedge is not convex;
 *    penumbra_face sums it in convex pieces (wedge_pieces_sum). */
int contact_faces(const PenumbraState* st, float3 p, float3 n, PnOccluder o,
                  __global const float4* planes, float eps_length, float3* limiting, int capacity,
                  float3* opposed) {
  int count = -1;
  float most = 2.0f;
  for (int j = 0; j < o.planeCount; ++j) {
    float4 pl = planes[o.firstPlane + j];
    if (dot(pl.xyz, p) - pl.w < -eps_length) continue; /* this face does not pass through P */
    if (count < 0) count = 0;
    bool holds_source = true;
    for (int i = 0; i < st->ns && holds_source; ++i)
      holds_source = dot(pl.xyz, st->sv[i]) <= PN_EPS_REL * length(st->sv[i]);
    if (holds_source) continue;
    if (count < capacity) limiting[count] = pl.xyz;
    ++count;
    if (dot(pl.xyz, n) < most) {
      most = dot(pl.xyz, n);
      *opposed = pl.xyz;
    }
  }
  return count;
}

/* The plain path's test (kept as the foundation had it): the bounding sphere against the pyramid
 * P + cone(face). */
inline bool sphere_outside_pyramid(float3 p, float3 n, PnOccluder o, PnSourceFace face,
                                   __global const float4* vertices) {
  float3 c = o.bound.xyz - p;
  float r = o.bound.w;
  if (dot(n, c) < -r) return true;
  const int m = face.vertexCount;
  float3 a = vertices[face.firstVertex].xyz - p;
  for (int i = 0; i < m; ++i) {
    float3 b = vertices[face.firstVertex + (i + 1 == m ? 0 : i + 1)].xyz - p;
    /* inside the pyramid: cross(a, b)·x < 0 for every side (see the orientation note below) */
    float3 side = cross(a, b);
    if (dot(side, c) > r * length(side)) return true;
    a = b;
  }
  return false;
}

/* Whether an occluder misses the pyramid P + cone(S') (S' side normals in st->sm): its bounding
 * sphere is below the horizon or outside a side plane; or, for a lane that sees the face through
 * an aperture (where the occluder's volume is the whole face's, not S''s), all its vertices are
 * outside a side plane by more than eps_length. */
bool outside_source_pyramid(const PenumbraState* st, float3 p, float3 n, PnOccluder o,
                            bool vertices, __global const float4* overts, float eps_length) {
  float3 c = o.bound.xyz - p;
  float r = o.bound.w;
  if (dot(n, c) < -r) return true;
  for (int i = 0; i < st->ns; ++i)
    if (dot(st->sm[i], c) > r) return true; /* (a zero normal never passes) */
  if (!vertices) return false;
  for (int i = 0; i < st->ns; ++i) {
    float3 m = st->sm[i]; /* a zero normal (no plane) never has the vertices outside */
    bool out = true;
    for (int k = 0; k < o.vertexCount && out; ++k)
      out = dot(m, overts[o.firstVertex + k].xyz - p) > eps_length;
    if (out) return true;
  }
  return false;
}

/* The contour edge e of an active occluder, hole-oriented, relative to P. False when e is not
 * on the contour. */
inline bool faces_point(PnOccluder o, int face, float3 p, __global const float4* planes,
                        float eps_length) {
  float4 pl = planes[o.firstPlane + face];
  return dot(pl.xyz, p) - pl.w > eps_length;
}

/* Whether a face sees P is tested per edge rather than kept in a bit mask, so that a solid may
 * have any number of faces (a finely faceted sphere has hundreds). */
inline bool contour_edge(int e, PnOccluder o, float3 p, __global const int4* edges,
                         __global const float4* overts, __global const float4* planes,
                         float eps_length, float3* a, float3* b) {
  int4 ed = edges[o.firstEdge + e];
  bool left_front = faces_point(o, ed.z, p, planes, eps_length);
  bool right_front = faces_point(o, ed.w, p, planes, eps_length);
  if (left_front == right_front) return false;
  /* Run it as the face that does not see P does: that face's loop goes from -> to when it is
   * the left face. */
  float3 from = overts[o.firstVertex + ed.x].xyz - p;
  float3 to = overts[o.firstVertex + ed.y].xyz - p;
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

/* The side planes' ids: S' edges first, then the active occluders' contour edges. */
#define PN_ID_CONTOUR PN_MAX_SOURCE_POLYGON
inline float3 plane_of(const PenumbraState* st, int id) {
  return id < PN_ID_CONTOUR ? st->sm[id] : st->cm[id - PN_ID_CONTOUR];
}

/* Integral over the visible parts of one boundary edge owned by region `owner` (-1 = source),
 * whose side plane has id `self` (its unit normal is plane_of(st, self)). */
void visible_edge_term(float3 a, float3 b, int owner, int self, float3 n, const PenumbraState* st,
                       int* error, PnSum* acc) {
  const float3 m_self = plane_of(st, self);
  if (no_plane(m_self)) return; /* its line passes through P: no solid angle */
  float lo[PN_MAX_VISIBLE_PIECES], hi[PN_MAX_VISIBLE_PIECES];
  int lo_id[PN_MAX_VISIBLE_PIECES], hi_id[PN_MAX_VISIBLE_PIECES];
  int pieces = 1;
  lo[0] = 0.0f;
  hi[0] = 1.0f;
  lo_id[0] = hi_id[0] = PN_ID_VERTEX;
  const float la = length(a), lb = length(b);

  if (owner >= 0) { /* an occluder edge counts only inside S' */
    float t0 = 0.0f, t1 = 1.0f;
    for (int i = 0; i < st->ns; ++i) {
      float3 m = st->sm[i];
      if (no_plane(m)) continue; /* repeated S' vertex: no side plane */
      float f0 = -dot(m, a), f1 = -dot(m, b);
      /* In a boundary plane of S': same visible side → the source (lower index) keeps it;
       * opposite → dropped. Either way this occluder edge is not counted. */
      if (in_plane(f0, f1, la, lb)) return;
      clip_interval_id(f0, f1, i, &t0, &t1, &lo_id[0], &hi_id[0]);
      if (!(t1 > t0)) return;
    }
    lo[0] = t0;
    hi[0] = t1;
  }

  for (int v = 0; v < st->na; ++v) {
    if (v == owner) continue;
    float t0 = 0.0f, t1 = 1.0f;
    int id0 = PN_ID_VERTEX, id1 = PN_ID_VERTEX;
    bool covers = true;
    for (int e = st->first_contour[v]; e < st->first_contour[v + 1] && covers; ++e) {
      float3 m = st->cm[e];      /* inside the occluder's cone: m·x > 0 */
      if (no_plane(m)) continue; /* P on the edge's line */
      float f0 = dot(m, a), f1 = dot(m, b);
      if (in_plane(f0, f1, la, lb)) {
        bool same_side = dot(m_self, m) > 0.0f;
        if (same_side && owner < v) covers = false; /* this edge is the one kept */
        continue;                                   /* otherwise the plane does not limit */
      }
      clip_interval_id(f0, f1, PN_ID_CONTOUR + e, &t0, &t1, &id0, &id1);
      if (!(t1 > t0)) covers = false;
    }
    if (!covers) continue;
    /* Subtract [t0, t1] from the sorted, disjoint visible pieces. */
    float nlo[PN_MAX_VISIBLE_PIECES], nhi[PN_MAX_VISIBLE_PIECES];
    int nlo_id[PN_MAX_VISIBLE_PIECES], nhi_id[PN_MAX_VISIBLE_PIECES];
    int count = 0;
    for (int k = 0; k < pieces; ++k) {
      if (t1 <= lo[k] || t0 >= hi[k]) {
        nlo[count] = lo[k];
        nhi[count] = hi[k];
        nlo_id[count] = lo_id[k];
        nhi_id[count] = hi_id[k];
        ++count;
        continue;
      }
      if (t0 > lo[k]) {
        nlo[count] = lo[k];
        nhi[count] = t0;
        nlo_id[count] = lo_id[k];
        nhi_id[count] = id0;
        ++count;
      }
      if (t1 < hi[k]) {
        if (count == PN_MAX_VISIBLE_PIECES) {
          *error |= PN_ERROR_TOO_MANY_PIECES;
          break;
        }
        nlo[count] = t1;
        nhi[count] = hi[k];
        nlo_id[count] = id1;
        nhi_id[count] = hi_id[k];
        ++count;
      }
    }
    pieces = count;
    for (int k = 0; k < pieces; ++k) {
      lo[k] = nlo[k];
      hi[k] = nhi[k];
      lo_id[k] = nlo_id[k];
      hi_id[k] = nhi_id[k];
    }
    if (pieces == 0) return;
  }

  for (int k = 0; k < pieces; ++k) {
    float3 p0 = edge_point(a, b, lo[k]), p1 = edge_point(a, b, hi[k]);
    if (lo_id[k] != PN_ID_VERTEX)
      p0 = crossing_point(m_self, self, plane_of(st, lo_id[k]), lo_id[k], p0);
    if (hi_id[k] != PN_ID_VERTEX)
      p1 = crossing_point(m_self, self, plane_of(st, hi_id[k]), hi_id[k], p1);
    pn_sum_add(acc, piece_term(p0, p1, n));
  }
}

/* E / (L/2) of the visible part of S' (st->sv) past the active occluders. */
float region_sum(PenumbraState* st, float3 n, int* error) {
  for (int i = 0; i < st->ns; ++i)
    st->sm[i] = side_normal(st->sv[i], st->sv[i + 1 == st->ns ? 0 : i + 1]);
  PnSum sum = {0.0f, 0.0f};
  for (int i = 0; i < st->ns; ++i)
    visible_edge_term(st->sv[i], st->sv[i + 1 == st->ns ? 0 : i + 1], -1, i, n, st, error, &sum);
  for (int u = 0; u < st->na; ++u)
    for (int e = st->first_contour[u]; e < st->first_contour[u + 1]; ++e)
      visible_edge_term(st->ca[e], st->cb[e], u, PN_ID_CONTOUR + e, n, st, error, &sum);
  return sum.s + sum.c;
}

/* S' minus the wedges of the solids P lies on the edge or corner of (contact_faces), as disjoint
 * convex pieces: for a wedge of faces f_1 … f_m the part of a piece outside the wedge is the
 * union over i of {f_i·x ≥ 0, f_j·x < 0 for j < i}; every piece is integrated like S' (the tie
 * rule holds for any convex region) and the pieces' shared sides cancel in the sum. */
float wedge_pieces_sum(PenumbraState* st, float3 n, const float3 (*wedge)[PN_MAX_WEDGE_FACES],
                       const int* wedge_faces, int wedges, int* error) {
  float3 base[PN_MAX_SOURCE_POLYGON];
  const int base_count = st->ns;
  for (int i = 0; i < base_count; ++i) base[i] = st->sv[i];
  int pieces = 1;
  for (int k = 0; k < wedges; ++k) pieces *= wedge_faces[k];
  PnSum sum = {0.0f, 0.0f};
  for (int piece = 0; piece < pieces; ++piece) {
    st->ns = base_count;
    for (int i = 0; i < base_count; ++i) st->sv[i] = base[i];
    int code = piece;
    for (int k = 0; k < wedges && st->ns >= 3; ++k) {
      const int chosen = code % wedge_faces[k];
      code /= wedge_faces[k];
      for (int j = 0; j < chosen && st->ns >= 3; ++j) clip_source(st, -wedge[k][j]);
      if (st->ns >= 3) clip_source(st, wedge[k][chosen]);
    }
    if (st->ns >= 3) pn_sum_add(&sum, region_sum(st, n, error));
  }
  return sum.s + sum.c;
}

/* `aperture`: P sees the face through its aperture (host/shadow/aperture.hpp); `corners` then
 * holds the visible rectangle relative to P, and occluders behind the aperture are skipped. */
float penumbra_face(float3 p, float3 n, int own, PnSourceFace face, PnPatchFace pf,
                    __global const int* candidates, int use_volumes,
                    __global const float4* vertices, __global const PnOccluder* occluders,
                    __global const float4* planes, __global const int4* edges,
                    __global const float4* overts, float eps_length, bool aperture,
                    const float3* corners, int* error) {
  if (dot(face.plane.xyz, p) - face.plane.w <= 0.0f) return 0.0f;
  PenumbraState st;

  /* S': the face (or its visible rectangle) clipped by the horizon plane through P
   * (Sutherland–Hodgman). */
  st.ns = 0;
  if (aperture) {
    for (int i = 0; i < 4; ++i) st.sv[i] = corners[i];
    st.ns = 4;
    clip_source(&st, n);
  } else {
    const int m = face.vertexCount;
    float3 a = vertices[face.firstVertex].xyz - p;
    float ha = dot(n, a);
    for (int i = 0; i < m; ++i) {
      float3 b = vertices[face.firstVertex + (i + 1 == m ? 0 : i + 1)].xyz - p;
      float hb = dot(n, b);
      if (ha >= 0.0f) st.sv[st.ns++] = a;
      if ((ha >= 0.0f) != (hb >= 0.0f)) st.sv[st.ns++] = a + (ha / (ha - hb)) * (b - a);
      a = b;
      ha = hb;
    }
  }
  if (st.ns < 3) return 0.0f;
  /* A face seen edge-on (every vertex of S' within the tolerance of the horizon, e.g. a source
   * corner exactly in P's tangent plane) gives nothing: its E is below PN_EPS_REL · π·L, and the
   * side planes of such a sliver have no direction, so occluder edges would be taken as inside it
   * and integrated as holes (found by the stress suite: E = -11 lx, bench/degenerate_stress). */
  float rise = 0.0f;
  for (int i = 0; i < st.ns; ++i) rise = fmax(rise, dot(n, st.sv[i]) / length(st.sv[i]));
  if (rise <= PN_EPS_REL) return 0.0f;

  for (int i = 0; i < st.ns; ++i)
    st.sm[i] = side_normal(st.sv[i], st.sv[i + 1 == st.ns ? 0 : i + 1]);

  /* One pass over the patch's occluders: those with a face that sees P are candidates (unless
   * P is outside their penumbra volume or they miss the pyramid to S'); those with none are
   * solids P lies on. */
  st.na = 0;
  st.first_contour[0] = 0;
  int contacts = 0;
  float3 wedge[PN_MAX_WEDGES][PN_MAX_WEDGE_FACES];
  int wedge_faces[PN_MAX_WEDGES];
  int wedges = 0;
  const int count = occluder_count(pf, face);
  for (int i = 0; i < count; ++i) {
    const int k = occluder_index(i, pf, face, candidates);
    PnOccluder o = occluders[k];
    if (aperture && o.behindAperture) continue;
    if (o.solid == own || occluder_separated(p, o, planes, eps_length)) continue;
    if (use_volumes && !in_penumbra_volume(p, o, planes, eps_length)) continue;
    bool any_front = false;
    for (int j = 0; j < o.planeCount && !any_front; ++j)
      any_front = faces_point(o, j, p, planes, eps_length);
    if (!any_front) {
      if (contacts == PN_MAX_CONTACTS) {
        *error |= PN_ERROR_TOO_MANY_CONTACTS;
        break;
      }
      ++contacts;
      float3 limiting[PN_MAX_WEDGE_FACES], opposed;
      const int m =
          contact_faces(&st, p, n, o, planes, eps_length, limiting, PN_MAX_WEDGE_FACES, &opposed);
      if (m < 0) continue;
      if (m == 0) return 0.0f;
      if (m >= 2 && m <= PN_MAX_WEDGE_FACES && wedges < PN_MAX_WEDGES) {
        for (int j = 0; j < m; ++j) wedge[wedges][j] = limiting[j];
        wedge_faces[wedges++] = m;
        continue;
      }
      /* One face, exactly; or (more wedges or faces than the pieces hold: P at a vertex where
       * many facets meet, a set of measure zero) the face most opposed to P's normal alone. */
      clip_source(&st, m == 1 ? limiting[0] : opposed);
      if (st.ns < 3) return 0.0f;
      for (int i = 0; i < st.ns; ++i)
        st.sm[i] = side_normal(st.sv[i], st.sv[i + 1 == st.ns ? 0 : i + 1]);
      continue;
    }
    if (use_volumes ? outside_source_pyramid(&st, p, n, o, aperture, overts, eps_length)
                    : sphere_outside_pyramid(p, n, o, face, vertices))
      continue;
    if (st.na == PN_MAX_ACTIVE_OCCLUDERS) {
      *error |= PN_ERROR_TOO_MANY_OCCLUDERS;
      break;
    }
    int c = st.first_contour[st.na];
    for (int e = 0; e < o.edgeCount; ++e) {
      float3 ea, eb;
      if (!contour_edge(e, o, p, edges, overts, planes, eps_length, &ea, &eb)) continue;
      if (c == PN_MAX_CONTOUR_EDGES) {
        *error |= PN_ERROR_TOO_MANY_CONTOUR_EDGES;
        break;
      }
      st.ca[c] = ea;
      st.cb[c] = eb;
      st.cm[c] = side_normal(ea, eb);
      ++c;
    }
    ++st.na;
    st.first_contour[st.na] = c;
  }

  const float sum = wedges == 0 ? region_sum(&st, n, error)
                                : wedge_pieces_sum(&st, n, wedge, wedge_faces, wedges, error);
  /* A visible region gives no negative light: a sum below 0 is the float round-off of an empty
   * one (an umbra's edge: -5e-6 lx where π·L = 3142 lx, bench/degenerate_stress). */
  return fmax(sum, 0.0f);
}

/* ---------------------------------------------------------------------------------------------
 * The penumbra path in eight lanes (culling only; the plain path keeps the scalar one above).
 * The same method and tie rule as penumbra_face, with every lane's view in one float8:
 *  - the active occluders are the union over the lanes (each with a lane mask), in candidate
 *    order, so "lower index" means the same in every lane;
 *  - every edge of an active occluder is kept with a per-lane contour mask and orientation;
 *  - S' is the face (or the lane's aperture rectangle) with each edge's part above the horizon
 *    and, where the horizon cuts it, the chord: its side planes are the face's edge planes and,
 *    in cut lanes, the horizon plane;
 *  - the visible parts of an edge are [lo, hi] minus the union of the intervals the other
 *    regions cover: a visible piece starts at lo or at the end of a covering interval that no
 *    other interval covers, and ends at the next interval's start or hi; each piece is one
 *    float8 edge term for the lanes that have it.
 * Lanes this path does not take (a solid touching P, an occluder with more faces than it tracks)
 * are returned in `scalar` for the scalar path; lanes whose occluders do not fit beside the other
 * lanes' (more occluders or edges than it holds) in `rest`: the kernel calls it again for those
 * lanes alone, and gives them to the scalar path when that does not help. */

#define PN_VEC_OCCLUDERS 32 /* active occluders per work-item and face */
#define PN_VEC_EDGES 192    /* their edges in all */
#define PN_VEC_FACES 16     /* faces of one occluder */
#define PN_VEC_SOURCE 8     /* vertices of the face */
#define PN_VEC_PASSES 4     /* calls per work-item and face, each on the lanes the last left */
#define PN_VEC_MASKS 64     /* candidates whose shadow-test lane masks are kept for this path */

/* An active occluder's edge in two parts: its side plane, which every other region's edges are
 * tested against (the hot loop of visible_edge_term8, so kept compact), and its ends. */
typedef struct {
  float8 mx, my, mz; /* unit side-plane normal along cross(a, b); 0: none */
  int8 on;           /* lanes where it is a contour edge with a side plane */
} EdgePlane8;

typedef struct {
  float8 ax, ay, az, bx, by, bz; /* hole-oriented per lane, relative to P */
  int8 on;                       /* lanes where it is a contour edge of the occluder */
} ContourEdge8;

/* The cone of directions from P to an occluder's bounding sphere: unit axis u and the sine and
 * cosine of its half-angle, grown by PN_VEC_CONE_MARGIN (2 and -2 where P is inside the
 * sphere). An edge whose great circle, or whose arc, stays outside it cannot be covered by the
 * occluder, which visible_edge_term8 then skips without walking its side planes. */
typedef struct {
  float8 ux, uy, uz, sin_a, cos_a;
} BoundCone8;

#define PN_VEC_CONE_MARGIN 1e-3f

typedef struct {
  EdgePlane8 p[PN_VEC_EDGES];
  ContourEdge8 e[PN_VEC_EDGES];
  BoundCone8 cone[PN_VEC_OCCLUDERS];
  int8 act[PN_VEC_OCCLUDERS];   /* the lanes each occluder is active in */
  int8 whole[PN_VEC_OCCLUDERS]; /* lanes where each of its contour edges has a side plane */
  int occ[PN_VEC_OCCLUDERS];    /* its index among the occluders */
  int first[PN_VEC_OCCLUDERS + 1];
  int na;
} Contours8;

inline void side_normal8(float8 ax, float8 ay, float8 az, float8 bx, float8 by, float8 bz,
                         float8* mx, float8* my, float8* mz) {
  float8 ex = bx - ax, ey = by - ay, ez = bz - az;
  float8 cx = ay * ez - az * ey, cy = az * ex - ax * ez, cz = ax * ey - ay * ex;
  float8 len = sqrt(cx * cx + cy * cy + cz * cz);
  float8 la = sqrt(ax * ax + ay * ay + az * az), lb = sqrt(bx * bx + by * by + bz * bz);
  int8 none = len <= PN_EPS_REL * la * lb;
  *mx = select(cx / len, (float8)(0.0f), none);
  *my = select(cy / len, (float8)(0.0f), none);
  *mz = select(cz / len, (float8)(0.0f), none);
}

inline float8 edge_point8(float8 a, float8 b, float8 t) {
  return select(b - (1.0f - t) * (b - a), a + t * (b - a), t <= 0.5f);
}

/* A piece end per lane where another region's side plane set it: the cross product of the two
 * unit side normals, in the order of their plane ids (crossing_point says why). */
typedef struct {
  float8 x, y, z;
  int8 set;
} PieceEnd8;

inline void piece_end_clear8(PieceEnd8* e) {
  e->x = e->y = e->z = 0.0f;
  e->set = 0;
}

/* The side planes' ids in eight lanes: S' edges 0 … m − 1, the chord m, then the contour store. */
#define PN_VEC_ID_CONTOUR (PN_VEC_SOURCE + 1)

/* clip_interval_id in eight lanes, on the lanes of `clip` (returns those where the interval is not
 * empty): id0 and id1 keep, per lane, the plane (its index k) that set each end. */
inline int8 clip_interval_id8(float8 f0, float8 f1, int8 clip, int k, float8* t0, float8* t1,
                              int8* id0, int8* id1) {
  int8 n0 = f0 < 0.0f, n1 = f1 < 0.0f;
  int8 enters = clip & n0 & ~n1, leaves = clip & ~n0 & n1;
  if (pn_any(enters | leaves)) { /* most planes do not cross the edge: no division */
    float8 t = f0 / (f0 - f1);
    int8 up0 = enters & (t > *t0), up1 = leaves & (t < *t1);
    *t0 = select(*t0, t, up0);
    *t1 = select(*t1, t, up1);
    *id0 = select(*id0, (int8)(k), up0);
    *id1 = select(*id1, (int8)(k), up1);
  }
  return ~(clip & n0 & n1) & (*t1 > *t0);
}

/* Once an interval is known to matter: the crossing points at its ends (id0, id1 from
 * clip_interval_id8: the index of the plane that set each end, -1 for none), each the cross
 * product of the edge's unit side normal ms (plane id `self`) and that plane's, in the order of
 * their ids. Plane k's normal is planes[k] and its id first_id + k. Done after the clipping, for
 * the intervals that are kept, and once per distinct plane among the lanes (usually one or two)
 * rather than at every plane that moves an end. */
inline void crossing_ends8(float8 msx, float8 msy, float8 msz, int self, const EdgePlane8* planes,
                           int first_id, int8 id0, int8 id1, int8 lanes, PieceEnd8* e0,
                           PieceEnd8* e1) {
  piece_end_clear8(e0);
  piece_end_clear8(e1);
  int8 left0 = lanes & (id0 >= 0), left1 = lanes & (id1 >= 0);
  while (pn_any(left0 | left1)) {
    const int k = __builtin_reduce_min(
        min(select((int8)(INT_MAX), id0, left0), select((int8)(INT_MAX), id1, left1)));
    const int id = first_id + k;
    int8 at0 = left0 & (id0 == k), at1 = left1 & (id1 == k);
    const EdgePlane8* c = &planes[k];
    float8 px = self < id ? msx : c->mx, py = self < id ? msy : c->my, pz = self < id ? msz : c->mz;
    float8 qx = self < id ? c->mx : msx, qy = self < id ? c->my : msy, qz = self < id ? c->mz : msz;
    float8 dx = py * qz - pz * qy, dy = pz * qx - px * qz, dz = px * qy - py * qx;
    e0->x = select(e0->x, dx, at0);
    e0->y = select(e0->y, dy, at0);
    e0->z = select(e0->z, dz, at0);
    e0->set |= at0;
    e1->x = select(e1->x, dx, at1);
    e1->y = select(e1->y, dy, at1);
    e1->z = select(e1->z, dz, at1);
    e1->set |= at1;
    left0 &= ~at0;
    left1 &= ~at1;
  }
}

/* The point of a piece end: the crossing direction where one was set and is well defined,
 * turned to the side of the edge's own point (px, py, pz) at t; that point elsewhere. Its length
 * does not matter: piece_term8 depends on directions only, and its cross product is accurate for
 * vectors of any lengths. */
inline void piece_point8(const PieceEnd8* e, float8* px, float8* py, float8* pz) {
  int8 use = e->set & (e->x * e->x + e->y * e->y + e->z * e->z > PN_EPS_REL * PN_EPS_REL);
  if (!pn_any(use)) return;
  float8 sign =
      select((float8)(1.0f), (float8)(-1.0f), e->x * *px + e->y * *py + e->z * *pz < 0.0f);
  *px = select(*px, sign * e->x, use);
  *py = select(*py, sign * e->y, use);
  *pz = select(*pz, sign * e->z, use);
}

inline float8 diff_of_products8(float8 x, float8 y, float8 z, float8 w) {
  float8 zw = z * w;
  return fma(x, y, -zw) + fma(-z, w, zw);
}

/* piece_term in eight lanes. */
inline float8 piece_term8(float8 ax, float8 ay, float8 az, float8 bx, float8 by, float8 bz,
                          float8 nx, float8 ny, float8 nz) {
  float8 cx = diff_of_products8(ay, bz, az, by), cy = diff_of_products8(az, bx, ax, bz),
         cz = diff_of_products8(ax, by, ay, bx);
  float8 s = sqrt(cx * cx + cy * cy + cz * cz);
  float8 term = -atan2(s, ax * bx + ay * by + az * bz) * (nx * cx + ny * cy + nz * cz) / s;
  return select(term, (float8)(0.0f), s <= 0.0f);
}

/* Integral over the visible parts of the edge a → b (per lane, from P) owned by region `owner`
 * (-1 = the source), within the parameter range [lo, hi] of the lanes in `on`. */
void visible_edge_term8(float8 ax, float8 ay, float8 az, float8 bx, float8 by, float8 bz,
                        float8 msx, float8 msy, float8 msz, int self, float8 lo, float8 hi,
                        const PieceEnd8* lo_end, const PieceEnd8* hi_end, int8 on, int owner,
                        float8 nx, float8 ny, float8 nz, const Contours8* cs, PnSum8* acc) {
  if (!pn_any(on)) return;
  float8 mex = ay * bz - az * by, mey = az * bx - ax * bz, mez = ax * by - ay * bx;
  float8 la = sqrt(ax * ax + ay * ay + az * az), lb = sqrt(bx * bx + by * by + bz * bz);
  /* For the bounding-cone test, set up at the first occluder that needs it: the unit normal of
   * the edge's great circle, the unit ends and, at each end, the circle's tangent pointing into
   * the arc. Where the edge's line passes near P (no circle) the test rejects nothing. */
  bool cone_ready = false;
  int8 arc = 0;
  float8 gx = 0.0f, gy = 0.0f, gz = 0.0f, aux = 0.0f, auy = 0.0f, auz = 0.0f, bux = 0.0f,
         buy = 0.0f, buz = 0.0f, tax = 0.0f, tay = 0.0f, taz = 0.0f, tbx = 0.0f, tby = 0.0f,
         tbz = 0.0f;
  /* The occluders that cover part of the edge in some lane, in order, with their intervals and
   * the crossing points at the intervals' ends (most active occluders cover none of it). */
  float8 c0[PN_VEC_OCCLUDERS], c1[PN_VEC_OCCLUDERS];
  PieceEnd8 e0[PN_VEC_OCCLUDERS], e1[PN_VEC_OCCLUDERS];
  int8 cov[PN_VEC_OCCLUDERS];
  int nc = 0;
  for (int v = 0; v < cs->na; ++v) {
    float8 t0 = 0.0f, t1 = 1.0f;
    int8 id0 = -1, id1 = -1;
    int8 covers = v == owner ? (int8)(0) : on & cs->act[v];
    if (pn_any(covers)) {
      if (!cone_ready) {
        cone_ready = true;
        float8 lm = sqrt(mex * mex + mey * mey + mez * mez);
        arc = lm > PN_EPS_REL * la * lb;
        float8 im = 1.0f / lm, ia = 1.0f / la, ib = 1.0f / lb;
        gx = mex * im;
        gy = mey * im;
        gz = mez * im;
        aux = ax * ia;
        auy = ay * ia;
        auz = az * ia;
        bux = bx * ib;
        buy = by * ib;
        buz = bz * ib;
        tax = gy * auz - gz * auy;
        tay = gz * aux - gx * auz;
        taz = gx * auy - gy * aux;
        tbx = buy * gz - buz * gy;
        tby = buz * gx - bux * gz;
        tbz = bux * gy - buy * gx;
      }
      const BoundCone8* k = &cs->cone[v];
      float8 d = k->ux * gx + k->uy * gy + k->uz * gz;
      float8 ea = k->ux * aux + k->uy * auy + k->uz * auz;
      float8 eb = k->ux * bux + k->uy * buy + k->uz * buz;
      int8 inside_arc = (k->ux * tax + k->uy * tay + k->uz * taz >= 0.0f) &
                        (k->ux * tbx + k->uy * tby + k->uz * tbz >= 0.0f);
      int8 misses = (fabs(d) > k->sin_a) | ((ea < k->cos_a) & (eb < k->cos_a) & ~inside_arc);
      covers &= ~(arc & misses);
    }
    for (int k = cs->first[v]; k < cs->first[v + 1] && pn_any(covers); ++k) {
      const EdgePlane8* e = &cs->p[k];
      int8 use = covers & e->on;
      if (!pn_any(use)) continue;
      float8 f0 = e->mx * ax + e->my * ay + e->mz * az; /* inside the occluder's cone: > 0 */
      float8 f1 = e->mx * bx + e->my * by + e->mz * bz;
      int8 inplane = use & (fabs(f0) <= PN_EPS_REL * la) & (fabs(f1) <= PN_EPS_REL * lb);
      if (owner < v) /* same visible side: this edge is the one kept */
        covers &= ~(inplane & ((mex * e->mx + mey * e->my + mez * e->mz) > 0.0f));
      covers &= clip_interval_id8(f0, f1, use & ~inplane, k, &t0, &t1, &id0, &id1);
    }
    if (!pn_any(covers)) continue;
    crossing_ends8(msx, msy, msz, self, cs->p, PN_VEC_ID_CONTOUR, id0, id1, covers, &e0[nc],
                   &e1[nc]);
    c0[nc] = t0;
    c1[nc] = t1;
    cov[nc++] = covers;
  }
  /* Visible pieces: candidate starts lo and each covering interval's end. */
  float8 starts[PN_VEC_OCCLUDERS + 1];
  int8 kept[PN_VEC_OCCLUDERS + 1];
  for (int j = -1; j < nc; ++j) {
    float8 st = j < 0 ? lo : c1[j];
    int8 valid = j < 0 ? on : cov[j];
    valid &= (st >= lo) & (st < hi);
    float8 end = hi;
    int8 end_at = -1; /* the covering interval whose start ends the piece; -1: hi */
    for (int w = 0; w < nc && pn_any(valid); ++w) {
      valid &= ~(cov[w] & (c0[w] <= st) & (st < c1[w]));
      int8 nearer = cov[w] & (c0[w] > st) & (c0[w] < end);
      end = select(end, c0[w], nearer);
      end_at = select(end_at, (int8)(w), nearer);
    }
    for (int i = 0; i <= j && pn_any(valid); ++i) valid &= ~(kept[i] & (starts[i] == st));
    starts[j + 1] = st;
    kept[j + 1] = valid;
    valid &= end > st;
    if (!pn_any(valid)) continue;
    float8 p0x = edge_point8(ax, bx, st), p0y = edge_point8(ay, by, st),
           p0z = edge_point8(az, bz, st);
    float8 p1x = edge_point8(ax, bx, end), p1y = edge_point8(ay, by, end),
           p1z = edge_point8(az, bz, end);
    piece_point8(j < 0 ? lo_end : &e1[j], &p0x, &p0y, &p0z);
    PieceEnd8 end_end = *hi_end;
    for (int w = 0; w < nc; ++w) {
      int8 at = valid & (end_at == w);
      if (!pn_any(at)) continue;
      end_end.x = select(end_end.x, e0[w].x, at);
      end_end.y = select(end_end.y, e0[w].y, at);
      end_end.z = select(end_end.z, e0[w].z, at);
      end_end.set = select(end_end.set, e0[w].set, at);
    }
    piece_point8(&end_end, &p1x, &p1y, &p1z);
    float8 term = piece_term8(p0x, p0y, p0z, p1x, p1y, p1z, nx, ny, nz);
    pn_sum_add8(acc, select((float8)(0.0f), term, valid));
  }
}

/* E of the face at the lanes in `asked` (others 0). Left out: in *rest the lanes whose occluders
 * did not fit beside the other lanes' (another call among themselves may hold them), in *scalar
 * those this path cannot take. */
float8 penumbra_face8(float8 px, float8 py, float8 pz, float8 nx, float8 ny, float8 nz, int8 own,
                      int8 asked, PnSourceFace face, PnPatchFace pf, __global const int* candidates,
                      ApertureView8 view, PnAperture ap, __global const float4* vertices,
                      __global const PnOccluder* occluders, __global const float4* planes,
                      __global const int4* edges, __global const float4* overts, float eps_length,
                      const int8* inside, int8* rest, int8* scalar) {
  *rest = 0;
  *scalar = 0;
  const int m = face.vertexCount;
  if (m > PN_VEC_SOURCE) {
    *scalar = asked;
    return 0.0f;
  }
  /* The source polygon per lane, from P: the face, or the lane's visible rectangle. */
  float8 sx[PN_VEC_SOURCE], sy[PN_VEC_SOURCE], sz[PN_VEC_SOURCE], sh[PN_VEC_SOURCE];
  for (int i = 0; i < m; ++i) {
    float4 q = vertices[face.firstVertex + i];
    sx[i] = q.x - px;
    sy[i] = q.y - py;
    sz[i] = q.z - pz;
    if (pn_any(view.use)) {
      float8 cx, cy, cz;
      aperture_corner8(view, ap, face.plane, i, &cx, &cy, &cz);
      sx[i] = select(sx[i], cx, view.use);
      sy[i] = select(sy[i], cy, view.use);
      sz[i] = select(sz[i], cz, view.use);
    }
    sh[i] = nx * sx[i] + ny * sy[i] + nz * sz[i];
  }
  /* Lanes behind the face, or that see it edge-on (penumbra_face), get 0. */
  float8 rise = 0.0f;
  for (int i = 0; i < m; ++i)
    rise = fmax(rise, sh[i] / sqrt(sx[i] * sx[i] + sy[i] * sy[i] + sz[i] * sz[i]));
  int8 lanes = asked &
               (face.plane.x * px + face.plane.y * py + face.plane.z * pz - face.plane.w > 0.0f) &
               (rise > PN_EPS_REL);
  if (!pn_any(lanes)) return 0.0f;
  /* Side planes of S': the face's edges, and the horizon where it cuts the face. */
  float8 smx[PN_VEC_SOURCE], smy[PN_VEC_SOURCE], smz[PN_VEC_SOURCE];
  float8 hx0 = 0.0f, hy0 = 0.0f, hz0 = 0.0f, hx1 = 0.0f, hy1 = 0.0f, hz1 = 0.0f; /* the chord */
  int8 has_exit = 0, has_entry = 0;
  for (int i = 0; i < m; ++i) {
    int j = i + 1 == m ? 0 : i + 1;
    side_normal8(sx[i], sy[i], sz[i], sx[j], sy[j], sz[j], &smx[i], &smy[i], &smz[i]);
    int8 a_in = sh[i] >= 0.0f, b_in = sh[j] >= 0.0f;
    float8 t = sh[i] / (sh[i] - sh[j]);
    float8 cx = edge_point8(sx[i], sx[j], t), cy = edge_point8(sy[i], sy[j], t),
           cz = edge_point8(sz[i], sz[j], t);
    int8 leaves = a_in & ~b_in, enters = ~a_in & b_in;
    hx0 = select(hx0, cx, leaves);
    hy0 = select(hy0, cy, leaves);
    hz0 = select(hz0, cz, leaves);
    hx1 = select(hx1, cx, enters);
    hy1 = select(hy1, cy, enters);
    hz1 = select(hz1, cz, enters);
    has_exit |= leaves;
    has_entry |= enters;
  }
  int8 cut = has_exit & has_entry;
  float8 cmx = 0.0f, cmy = 0.0f, cmz = 0.0f; /* the chord's side normal */
  if (pn_any(cut)) side_normal8(hx0, hy0, hz0, hx1, hy1, hz1, &cmx, &cmy, &cmz);
  EdgePlane8 sides[PN_VEC_SOURCE + 1]; /* S' side planes by id, for crossing_ends8 */
  for (int i = 0; i < m; ++i) {
    sides[i].mx = smx[i];
    sides[i].my = smy[i];
    sides[i].mz = smz[i];
  }
  sides[m].mx = cmx;
  sides[m].my = cmy;
  sides[m].mz = cmz;

  /* The active occluders and their edges. */
  Contours8 cs;
  cs.na = 0;
  cs.first[0] = 0;
  const int count = occluder_count(pf, face);
  for (int i = 0; i < count; ++i) {
    int8 act = lanes & ~(*rest | *scalar); /* left: not this call's */
    /* The first PN_VEC_MASKS candidates come with shadow_tests8's lanes (its own solid, behind
     * the aperture, the penumbra volume, the aperture's pyramid): only what it does not test. */
    if (i < PN_VEC_MASKS) act &= inside[i];
    if (!pn_any(act)) continue;
    PnOccluder o = occluders[occluder_index(i, pf, face, candidates)];
    if (i >= PN_VEC_MASKS) {
      act &= own != (int8)(o.solid);
      if (o.behindAperture) act &= ~view.use;
      for (int j = 0; j < o.penumbraCount && pn_any(act); ++j) {
        float4 pl = planes[o.firstPenumbra + j];
        act &= (pl.x * px + pl.y * py + pl.z * pz - pl.w) <= eps_length;
      }
    }
    for (int j = 0; j < o.separatingCount && pn_any(act); ++j) {
      float4 pl = planes[o.firstSeparating + j];
      act &= (pl.x * px + pl.y * py + pl.z * pz - pl.w) < -eps_length;
    }
    if (!pn_any(act)) continue;
    /* The bounding sphere against the pyramid P + cone(S'). */
    float8 cx = o.bound.x - px, cy = o.bound.y - py, cz = o.bound.z - pz;
    act &= (nx * cx + ny * cy + nz * cz) >= -o.bound.w;
    for (int j = 0; j < m && pn_any(act); ++j)
      act &= (smx[j] * cx + smy[j] * cy + smz[j] * cz) <= o.bound.w;
    if (i >= PN_VEC_MASKS && pn_any(act & view.use))
      act &= ~(view.use &
               misses_aperture_view8(px, py, pz, view, ap, face.plane, o, overts, eps_length));
    if (!pn_any(act)) continue;
    if (o.planeCount > PN_VEC_FACES) {
      *scalar |= act;
      continue;
    }
    if (cs.na == PN_VEC_OCCLUDERS) {
      *rest |= act;
      continue;
    }
    int8 front[PN_VEC_FACES];
    int8 any_front = 0;
    for (int j = 0; j < o.planeCount; ++j) {
      float4 pl = planes[o.firstPlane + j];
      front[j] = (pl.x * px + pl.y * py + pl.z * pz - pl.w) > eps_length;
      any_front |= front[j];
    }
    *scalar |= act & ~any_front; /* P lies on this solid: the scalar path clips S' by it */
    act &= any_front;
    if (!pn_any(act)) continue;
    /* Only the edges on some lane's contour are kept (a box has 12 edges, 4 to 6 on a contour). */
    int c = cs.first[cs.na];
    bool full = false;
    for (int k = 0; k < o.edgeCount; ++k) {
      int4 ed = edges[o.firstEdge + k];
      int8 lf = front[ed.z], rf = front[ed.w];
      int8 on = act & (lf ^ rf);
      if (!pn_any(on)) continue;
      if (c == PN_VEC_EDGES) {
        full = true;
        break;
      }
      float4 f = overts[o.firstVertex + ed.x], g = overts[o.firstVertex + ed.y];
      float8 fx = f.x - px, fy = f.y - py, fz = f.z - pz;
      float8 gx = g.x - px, gy = g.y - py, gz = g.z - pz;
      EdgePlane8* ep = &cs.p[c];
      ContourEdge8* e = &cs.e[c++];
      /* run as the face that does not see P does (contour_edge) */
      e->ax = select(fx, gx, lf);
      e->ay = select(fy, gy, lf);
      e->az = select(fz, gz, lf);
      e->bx = select(gx, fx, lf);
      e->by = select(gy, fy, lf);
      e->bz = select(gz, fz, lf);
      side_normal8(e->ax, e->ay, e->az, e->bx, e->by, e->bz, &ep->mx, &ep->my, &ep->mz);
      e->on = on;
      ep->on = on & ((ep->mx != 0.0f) | (ep->my != 0.0f) | (ep->mz != 0.0f));
    }
    if (full) { /* this occluder's edges do not fit: dropped, its lanes left for another call */
      *rest |= act;
      continue;
    }
    int8 whole = act;
    for (int k = cs.first[cs.na]; k < c; ++k) whole &= ~(cs.e[k].on & ~cs.p[k].on);
    cs.whole[cs.na] = whole;
    cs.occ[cs.na] = occluder_index(i, pf, face, candidates);
    BoundCone8* k = &cs.cone[cs.na];
    float8 dist = sqrt(cx * cx + cy * cy + cz * cz);
    float8 sin_a = o.bound.w / dist;
    int8 outside = dist > o.bound.w;
    k->ux = cx / dist;
    k->uy = cy / dist;
    k->uz = cz / dist;
    k->sin_a = select((float8)(2.0f), sin_a + PN_VEC_CONE_MARGIN, outside);
    k->cos_a = select((float8)(-2.0f), sqrt(fmax(1.0f - sin_a * sin_a, 0.0f)) - PN_VEC_CONE_MARGIN,
                      outside);
    cs.act[cs.na] = act;
    ++cs.na;
    cs.first[cs.na] = c;
  }
  lanes &= ~(*rest | *scalar);

  /* Occluders hidden behind another: where every vertex of u lies inside v's cone (inside each
   * side plane of v's contour by more than eps_length), u's cone lies strictly inside v's, so u
   * adds nothing to the union: it covers no edge v does not cover more, and its own edges are
   * covered. Its lanes are dropped; the pieces, and so the sums, are the same without it. */
  for (int u = 0; u < cs.na && cs.na > 1; ++u) {
    PnOccluder ou = occluders[cs.occ[u]];
    int8 hidden_all = 0;
    for (int v = 0; v < cs.na && pn_any(cs.act[u] & ~hidden_all); ++v) {
      if (v == u) continue;
      int8 hidden = cs.act[u] & cs.act[v] & cs.whole[v] & ~hidden_all;
      /* If every vertex of u is inside v's cone, so is u's centroid, the axis of u's bounding
       * cone: outside v's bounding cone (grown by its margin), u is not hidden by v. Most pairs
       * end here, before the test of u's vertices against v's planes. */
      const BoundCone8* ku = &cs.cone[u];
      const BoundCone8* kv = &cs.cone[v];
      hidden &= ku->ux * kv->ux + ku->uy * kv->uy + ku->uz * kv->uz >= kv->cos_a;
      for (int k = cs.first[v]; k < cs.first[v + 1] && pn_any(hidden); ++k) {
        const EdgePlane8* e = &cs.p[k];
        if (!pn_any(hidden & e->on)) continue;
        for (int q = 0; q < ou.vertexCount && pn_any(hidden); ++q) {
          float4 x = overts[ou.firstVertex + q];
          hidden &=
              ~e->on | (e->mx * (x.x - px) + e->my * (x.y - py) + e->mz * (x.z - pz) > eps_length);
        }
      }
      hidden_all |= hidden;
    }
    if (!pn_any(hidden_all)) continue;
    cs.act[u] &= ~hidden_all; /* (a dropped u hides nothing itself) */
    cs.whole[u] &= ~hidden_all;
    for (int k = cs.first[u]; k < cs.first[u + 1]; ++k) {
      cs.p[k].on &= ~hidden_all;
      cs.e[k].on &= ~hidden_all;
    }
  }

  PnSum8 sum = {0.0f, 0.0f};
  /* (a) The source's edges above the horizon, and the chord. Their ends are vertices or on the
   * horizon, where the edge and the chord compute the same point. */
  PieceEnd8 none;
  piece_end_clear8(&none);
  for (int i = 0; i < m; ++i) {
    int j = i + 1 == m ? 0 : i + 1;
    int8 a_in = sh[i] >= 0.0f, b_in = sh[j] >= 0.0f;
    float8 t = sh[i] / (sh[i] - sh[j]);
    float8 lo = select((float8)(0.0f), t, ~a_in), hi = select((float8)(1.0f), t, ~b_in);
    visible_edge_term8(sx[i], sy[i], sz[i], sx[j], sy[j], sz[j], smx[i], smy[i], smz[i], i, lo, hi,
                       &none, &none, lanes & (a_in | b_in), -1, nx, ny, nz, &cs, &sum);
  }
  visible_edge_term8(hx0, hy0, hz0, hx1, hy1, hz1, cmx, cmy, cmz, m, (float8)(0.0f), (float8)(1.0f),
                     &none, &none, lanes & cut, -1, nx, ny, nz, &cs, &sum);
  /* (b) The occluders' contour edges inside S', as holes. */
  for (int u = 0; u < cs.na; ++u)
    for (int k = cs.first[u]; k < cs.first[u + 1]; ++k) {
      const ContourEdge8* e = &cs.e[k];
      int8 on = lanes & e->on;
      if (!pn_any(on)) continue;
      float8 la = sqrt(e->ax * e->ax + e->ay * e->ay + e->az * e->az);
      float8 lb = sqrt(e->bx * e->bx + e->by * e->by + e->bz * e->bz);
      const EdgePlane8* ep = &cs.p[k];
      float8 t0 = 0.0f, t1 = 1.0f;
      int8 id0 = -1, id1 = -1;
      for (int i = 0; i <= m && pn_any(on); ++i) {
        float8 mx = i < m ? smx[i] : cmx, my = i < m ? smy[i] : cmy, mz = i < m ? smz[i] : cmz;
        int8 use = on & ((mx != 0.0f) | (my != 0.0f) | (mz != 0.0f));
        if (i == m) use &= cut;
        if (!pn_any(use)) continue;
        float8 f0 = -(mx * e->ax + my * e->ay + mz * e->az);
        float8 f1 = -(mx * e->bx + my * e->by + mz * e->bz);
        /* In a side plane of S': the source keeps it, or the visible region is empty there. */
        int8 inplane = use & (fabs(f0) <= PN_EPS_REL * la) & (fabs(f1) <= PN_EPS_REL * lb);
        on &= ~inplane;
        on &= clip_interval_id8(f0, f1, use & ~inplane, i, &t0, &t1, &id0, &id1);
      }
      if (!pn_any(on)) continue;
      PieceEnd8 lo_end, hi_end;
      crossing_ends8(ep->mx, ep->my, ep->mz, PN_VEC_ID_CONTOUR + k, sides, 0, id0, id1, on, &lo_end,
                     &hi_end);
      visible_edge_term8(e->ax, e->ay, e->az, e->bx, e->by, e->bz, ep->mx, ep->my, ep->mz,
                         PN_VEC_ID_CONTOUR + k, t0, t1, &lo_end, &hi_end, on, u, nx, ny, nz, &cs,
                         &sum);
    }
  return select((float8)(0.0f), fmax(sum.s + sum.c, 0.0f), lanes);
}

/* ---------------------------------------------------------------------------------------------
 * Shadow tests of one face for eight lanes (DESIGN.md step 3). With volumes: a lane deeper than
 * eps inside an umbra volume gets 0; one inside a penumbra volume (grown by eps) takes the
 * penumbra path; the rest keep the unoccluded value. Without (the plain path): a lane takes the
 * penumbra path unless every occluder is its own solid or separated from the face. */

typedef struct {
  int8 umbra;  /* some occluder hides the whole face */
  int8 shaded; /* some occluder may block part of it: the penumbra path */
} ShadowTests;

ShadowTests shadow_tests8(float8 px, float8 py, float8 pz, int8 own, PnSourceFace face,
                          PnPatchFace pf, __global const int* candidates, int use_volumes,
                          ApertureView8 view, PnAperture ap, __global const PnOccluder* occluders,
                          __global const float4* planes, __global const float4* overts,
                          float eps_length, int8* inside_out) {
  const int8 aperture = view.use;
  ShadowTests t;
  t.umbra = 0;
  t.shaded = 0;
  const int count = occluder_count(pf, face);
  for (int i = 0; i < count; ++i) {
    PnOccluder o = occluders[occluder_index(i, pf, face, candidates)];
    int8 inside = own != (int8)(o.solid);
    if (o.behindAperture) inside &= ~aperture; /* lanes that see the face through A */
    if (use_volumes) {
      if (i < PN_VEC_MASKS) inside_out[i] = 0;
      for (int j = 0; j < o.penumbraCount && pn_any(inside); ++j) {
        float4 pl = planes[o.firstPenumbra + j];
        inside &= (pl.x * px + pl.y * py + pl.z * pz - pl.w) <= eps_length;
      }
      if (!pn_any(inside)) continue;
      /* The volume is the occluder's against the whole face; lanes that see only a rectangle of
       * it through an aperture drop the occluder when it misses the pyramid to that rectangle. */
      if (pn_any(inside & aperture)) {
        inside &= ~(aperture &
                    misses_aperture_view8(px, py, pz, view, ap, face.plane, o, overts, eps_length));
        if (!pn_any(inside)) continue;
      }
      if (i < PN_VEC_MASKS) inside_out[i] = inside;
      t.shaded |= inside;
      if (o.umbraCount == 0) continue;
      int8 hidden = inside;
      for (int j = 0; j < o.umbraCount && pn_any(hidden); ++j) {
        float4 pl = planes[o.firstUmbra + j];
        hidden &= (pl.x * px + pl.y * py + pl.z * pz - pl.w) < -eps_length;
      }
      t.umbra |= hidden;
    } else {
      for (int j = 0; j < o.separatingCount; ++j) {
        float4 pl = planes[o.firstSeparating + j];
        inside &= (pl.x * px + pl.y * py + pl.z * pz - pl.w) < -eps_length;
      }
      t.shaded |= inside;
    }
  }
  t.shaded &= ~t.umbra;
  return t;
}

/* ---------------------------------------------------------------------------------------------
 * The kernel: E (lx) at PN_LANES points per work-item, summed over every source face, and each
 * point's shadow class per source (host/shadow/shadow_class.hpp: bit 0 some light arrives, bit 1
 * an occluder may block), written source by source with row length class_stride.
 * Points are structure-of-arrays, padded by the host to a multiple of PN_LANES.
 * use_volumes: 0 the plain path (every occluder, separating planes, scalar penumbra path); bit 0
 * culling (face classes, candidates, volumes, apertures); bit 1 with it, the eight-lane penumbra
 * path. */

__kernel void illuminance(__global const float* px_, __global const float* py_,
                          __global const float* pz_, __global const float* nx_,
                          __global const float* ny_, __global const float* nz_,
                          __global const int* own_, __global const PnSourceFace* faces,
                          const int face_count, __global const float4* vertices,
                          __global const PnOccluder* occluders, __global const float4* planes,
                          __global const int4* edges, __global const float4* overts,
                          const float eps_length, __global const PnPatchFace* patch_faces,
                          __global const int* candidates, __global const PnAperture* apertures,
                          const int use_volumes, const int per_source, __global float* out,
                          __global int* errors, __global uchar* classes, const int class_stride) {
  const size_t g = get_global_id(0);
  float8 px = vload8(g, px_), py = vload8(g, py_), pz = vload8(g, pz_);
  float8 nx = vload8(g, nx_), ny = vload8(g, ny_), nz = vload8(g, nz_);
  int8 own = vload8(g, own_);
  float lane_px[PN_LANES], lane_py[PN_LANES], lane_pz[PN_LANES];
  float lane_nx[PN_LANES], lane_ny[PN_LANES], lane_nz[PN_LANES];
  int lane_own[PN_LANES];
  vstore8(px, 0, lane_px);
  vstore8(py, 0, lane_py);
  vstore8(pz, 0, lane_pz);
  vstore8(nx, 0, lane_nx);
  vstore8(ny, 0, lane_ny);
  vstore8(nz, 0, lane_nz);
  vstore8(own, 0, lane_own);

  /* per_source: out holds E per source ([source][padded point], like classes); else the sum. */
  PnSum8 e_total = {0.0f, 0.0f}, e_source = {0.0f, 0.0f};
  int8 reaches = 0, blocked = 0; /* per source, reset after its last face */
  int error = 0;
  for (int f = 0; f < face_count; ++f) {
    PnSourceFace face = faces[f];
    PnPatchFace pf = patch_faces[g * face_count + f];
    if (pf.faceClass == PN_CLASS_UMBRA) /* the host found every lane in one occluder's umbra */
      blocked |= ((int8)(pf.facingLanes) >> (int8)(0, 1, 2, 3, 4, 5, 6, 7)) & 1;
    else if (pf.faceClass != PN_CLASS_C) { /* class C: nothing from this face (Nishita eq. 3) */
      /* Lanes that see the face through its aperture (culling only): its visible rectangle;
       * `dark` lanes see none of it past the wall. */
      ApertureView8 view;
      PnAperture ap;
      view.use = 0;
      view.u0 = view.u1 = view.v0 = view.v1 = view.depth = 0.0f;
      if (use_volumes && face.aperture >= 0) {
        ap = apertures[face.aperture];
        view = aperture_view8(px, py, pz, face, ap, eps_length);
      }
      int8 dark = view.use & ((view.u1 <= view.u0) | (view.v1 <= view.v0));
      float8 e_face = 0.0f;
      if (!all(view.use))
        e_face = horizon_cuts8(px, py, pz, nx, ny, nz, face, vertices)
                     ? unoccluded_face8(px, py, pz, nx, ny, nz, face, vertices)
                     : whole_face8(px, py, pz, nx, ny, nz, face, vertices);
      if (pn_any(view.use & ~dark))
        e_face = select(e_face, unoccluded_aperture8(view, ap, face.plane, nx, ny, nz), view.use);
      e_face = select(e_face, (float8)(0.0f), dark);
      int8 facing = e_face > 0.0f;
      int8 inside[PN_VEC_MASKS]; /* per candidate, the lanes in its penumbra volume */
      ShadowTests t = shadow_tests8(px, py, pz, own, face, pf, candidates, use_volumes, view, ap,
                                    occluders, planes, overts, eps_length, inside);
      t.shaded &= ~dark;
      t.umbra |= dark;
      facing |= dark;
      e_face = select(e_face, (float8)(0.0f), t.umbra);
      int8 scalar_lanes = t.shaded;
      /* The eight-lane path; the lanes whose occluders it could not hold beside the others' get
       * another call among themselves, whose union of occluders is smaller, while that helps. */
      if (use_volumes & 2) {
        int8 pending = t.shaded;
        scalar_lanes = 0;
        for (int pass = 0; pass < PN_VEC_PASSES && pn_any(pending); ++pass) {
          int8 asked = pending, scalar;
          float8 e_pen = penumbra_face8(px, py, pz, nx, ny, nz, own, asked, face, pf, candidates,
                                        view, ap, vertices, occluders, planes, edges, overts,
                                        eps_length, inside, &pending, &scalar);
          scalar_lanes |= scalar;
          int8 done = asked & ~(pending | scalar);
          e_face = select(e_face, e_pen, done);
          if (!pn_any(done)) break; /* no progress: what is left goes scalar */
        }
        scalar_lanes |= pending;
      }
      if (pn_any(scalar_lanes)) {
        float lane_e[PN_LANES];
        int lane_shaded[PN_LANES];
        vstore8(e_face, 0, lane_e);
        vstore8(scalar_lanes, 0, lane_shaded);
        int lane_ap[PN_LANES];
        float lane_cx[4][PN_LANES], lane_cy[4][PN_LANES], lane_cz[4][PN_LANES];
        vstore8(view.use, 0, lane_ap);
        if (pn_any(view.use & scalar_lanes))
          for (int i = 0; i < 4; ++i) {
            float8 cx, cy, cz;
            aperture_corner8(view, ap, face.plane, i, &cx, &cy, &cz);
            vstore8(cx, 0, lane_cx[i]);
            vstore8(cy, 0, lane_cy[i]);
            vstore8(cz, 0, lane_cz[i]);
          }
        for (int l = 0; l < PN_LANES; ++l) {
          if (!lane_shaded[l]) continue;
          float3 p = (float3)(lane_px[l], lane_py[l], lane_pz[l]);
          float3 n = (float3)(lane_nx[l], lane_ny[l], lane_nz[l]);
          float3 corners[4];
          if (lane_ap[l])
            for (int i = 0; i < 4; ++i)
              corners[i] = (float3)(lane_cx[i][l], lane_cy[i][l], lane_cz[i][l]);
          lane_e[l] = penumbra_face(p, n, lane_own[l], face, pf, candidates, use_volumes, vertices,
                                    occluders, planes, edges, overts, eps_length, lane_ap[l] != 0,
                                    corners, &error);
        }
        e_face = vload8(0, lane_e);
      }
      pn_sum_add8(&e_source, face.halfLuminance * e_face);
      reaches |= facing & ~t.umbra;
      blocked |= facing & (t.shaded | t.umbra);
    }
    if (f + 1 == face_count || faces[f + 1].source != face.source) {
      int8 cls = (reaches & 1) | ((blocked & 1) << 1);
      vstore8(convert_uchar8(cls), 0, classes + (size_t)face.source * class_stride + g * PN_LANES);
      if (per_source)
        vstore8(e_source.s + e_source.c, 0,
                out + (size_t)face.source * class_stride + g * PN_LANES);
      pn_sum_add8(&e_total, e_source.s);
      pn_sum_add8(&e_total, e_source.c);
      e_source.s = e_source.c = 0.0f;
      reaches = 0;
      blocked = 0;
    }
  }
  if (!per_source) vstore8(e_total.s + e_total.c, g, out);
  errors[g] = error;
}
