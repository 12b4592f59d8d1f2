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

/* ---------------------------------------------------------------------------------------------
 * Lambert's term of one edge, scalar and in eight lanes. a, b are vectors from P. */

inline float edge_term(float3 a, float3 b, float3 n) {
  float3 c = cross(b, a);
  float s = length(c);
  /* A zero-length edge, or one whose line passes through P, spans no solid angle. */
  if (!(s > 0.0f)) return 0.0f;
  return atan2(s, dot(a, b)) * dot(n, c) / s;
}

inline float8 edge_term8(float8 ax, float8 ay, float8 az, float8 bx, float8 by, float8 bz,
                         float8 nx, float8 ny, float8 nz) {
  float8 cx = by * az - bz * ay;
  float8 cy = bz * ax - bx * az;
  float8 cz = bx * ay - by * ax;
  float8 s = sqrt(cx * cx + cy * cy + cz * cz);
  float8 theta = atan2(s, ax * bx + ay * by + az * bz);
  float8 term = theta * (nx * cx + ny * cy + nz * cz) / s;
  return select(term, (float8)(0.0f), s <= 0.0f);
}

/* ---------------------------------------------------------------------------------------------
 * Unoccluded face, eight lanes: the face clipped by each lane's horizon plane (Nishita's type
 * B), streamed edge by edge. A convex face leaves the horizon once (exit) and re-enters once
 * (entry); the chord exit → entry lies in the horizon plane and closes the clipped contour. */

inline float8 unoccluded_face8(float8 px, float8 py, float8 pz, float8 nx, float8 ny, float8 nz,
                               PnSourceFace face, __global const float4* vertices) {
  float8 sum = 0.0f;
  float8 exx = 0.0f, exy = 0.0f, exz = 0.0f, enx = 0.0f, eny = 0.0f, enz = 0.0f;
  int8 has_exit = 0, has_entry = 0;
  const int m = face.vertexCount;
  float4 q = vertices[face.firstVertex];
  float8 ax = q.x - px, ay = q.y - py, az = q.z - pz;
  float8 ha = nx * ax + ny * ay + nz * az;
  for (int i = 0; i < m; ++i) {
    q = vertices[face.firstVertex + (i + 1 == m ? 0 : i + 1)];
    float8 bx = q.x - px, by = q.y - py, bz = q.z - pz;
    float8 hb = nx * bx + ny * by + nz * bz;
    int8 a_in = ha >= 0.0f, b_in = hb >= 0.0f;
    float8 t = ha / (ha - hb); /* used only where exactly one end is above the horizon */
    float8 cx = ax + t * (bx - ax), cy = ay + t * (by - ay), cz = az + t * (bz - az);
    float8 term =
        edge_term8(select(cx, ax, a_in), select(cy, ay, a_in), select(cz, az, a_in),
                   select(cx, bx, b_in), select(cy, by, b_in), select(cz, bz, b_in), nx, ny, nz);
    sum += select((float8)(0.0f), term, a_in | b_in);
    int8 leaves = a_in & ~b_in, enters = ~a_in & b_in;
    exx = select(exx, cx, leaves);
    exy = select(exy, cy, leaves);
    exz = select(exz, cz, leaves);
    enx = select(enx, cx, enters);
    eny = select(eny, cy, enters);
    enz = select(enz, cz, enters);
    has_exit |= leaves;
    has_entry |= enters;
    ax = bx;
    ay = by;
    az = bz;
    ha = hb;
  }
  int8 cut = has_exit & has_entry;
  if (any(cut)) /* most lanes see whole faces: skip the chord's atan2 when none is cut */
    sum += select((float8)(0.0f), edge_term8(exx, exy, exz, enx, eny, enz, nx, ny, nz), cut);
  /* Only points strictly in front of the face see it. */
  float8 front = face.plane.x * px + face.plane.y * py + face.plane.z * pz - face.plane.w;
  return select((float8)(0.0f), sum, front > 0.0f);
}

/* ---------------------------------------------------------------------------------------------
 * Occluder culling shared by both paths. An occluder cannot shade P from the face when
 *  - P lies on it (the solid P belongs to), or
 *  - one of its separating planes (faces whose closed outside holds the whole source face) has
 *    P in its closed outside too: every segment P→source then stays in that half-space, or
 *  - its bounding sphere misses the pyramid P + cone(face) (outside one side plane or wholly
 *    below the horizon). */

inline bool occluder_separated(float3 p, PnOccluder o, __global const float4* planes,
                               float eps_length) {
  for (int j = 0; j < o.separatingCount; ++j) {
    float4 pl = planes[o.firstSeparating + j];
    if (dot(pl.xyz, p) - pl.w >= -eps_length) return true;
  }
  return false;
}

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

typedef struct {
  /* S' vertices, relative to P: each clip by a plane adds at most one vertex */
  float3 sv[PN_MAX_SOURCE_VERTICES + 1 + PN_MAX_CONTACTS];
  int ns;
  int active[PN_MAX_ACTIVE_OCCLUDERS];
  ulong front[PN_MAX_ACTIVE_OCCLUDERS]; /* bit f: face f of the occluder sees P */
  int na;
} PenumbraState;

/* Keeps the part of S' with keep·x >= 0 (a plane through P; Sutherland–Hodgman). */
void clip_source(PenumbraState* st, float3 keep) {
  float3 out[PN_MAX_SOURCE_VERTICES + 1 + PN_MAX_CONTACTS];
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
 * dark). One face left: S' is clipped by it, exactly. None left: P sees nothing of the source
 * face. Two or more (P on an edge or corner that also cuts the pyramid to the source, a set of
 * measure zero): the face most opposed to P's normal is taken. A point strictly inside (no face
 * through P) is flagged by the host and left alone. False when nothing of S' is left. */
bool clip_by_contact(PenumbraState* st, float3 p, float3 n, PnOccluder o,
                     __global const float4* planes, float eps_length) {
  bool touches = false;
  int limiting = -1;
  float opposed = 2.0f;
  for (int j = 0; j < o.planeCount; ++j) {
    float4 pl = planes[o.firstPlane + j];
    if (dot(pl.xyz, p) - pl.w < -eps_length) continue; /* this face does not pass through P */
    touches = true;
    bool holds_source = true;
    for (int i = 0; i < st->ns && holds_source; ++i)
      holds_source = dot(pl.xyz, st->sv[i]) <= PN_EPS_REL * length(st->sv[i]);
    if (!holds_source && dot(pl.xyz, n) < opposed) {
      opposed = dot(pl.xyz, n);
      limiting = j;
    }
  }
  if (!touches) return true;
  if (limiting < 0) return false;
  clip_source(st, planes[o.firstPlane + limiting].xyz);
  return st->ns >= 3;
}

/* The contour edge e of an active occluder, hole-oriented, relative to P. False when e is not
 * on the contour. */
inline bool contour_edge(int e, PnOccluder o, ulong front, float3 p, __global const int4* edges,
                         __global const float4* overts, float3* a, float3* b) {
  int4 ed = edges[o.firstEdge + e];
  bool left_front = (front >> ed.z) & 1UL;
  bool right_front = (front >> ed.w) & 1UL;
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

/* Clips [*t0, *t1] to {t : f0 + t (f1 - f0) >= 0}. */
inline void clip_interval(float f0, float f1, float* t0, float* t1) {
  if (f0 >= 0.0f && f1 >= 0.0f) return;
  if (f0 < 0.0f && f1 < 0.0f) {
    *t1 = *t0 - 1.0f;
    return;
  }
  float t = f0 / (f0 - f1);
  if (f0 < 0.0f)
    *t0 = fmax(*t0, t);
  else
    *t1 = fmin(*t1, t);
}

/* A side plane through P and the segment (a, b) is undefined when the segment is a point or
 * its line passes through P. */
inline bool degenerate_side(float3 m, float3 a, float3 b) {
  return length(m) <= PN_EPS_REL * length(a) * length(b);
}

/* Does the edge (a, b) lie in the plane through P with normal m? Normalised so the test reads
 * as the sine of the angle between the plane and each end's direction. */
inline bool in_plane(float3 m, float3 a, float3 b, float f0, float f1) {
  float lm = length(m);
  return fabs(f0) <= PN_EPS_REL * lm * length(a) && fabs(f1) <= PN_EPS_REL * lm * length(b);
}

/* Integral over the visible parts of one boundary edge owned by region `owner` (-1 = source). */
float visible_edge_term(float3 a, float3 b, int owner, float3 n, float3 p, const PenumbraState* st,
                        __global const PnOccluder* occluders, __global const int4* edges,
                        __global const float4* overts, int* error) {
  float lo[PN_MAX_VISIBLE_PIECES], hi[PN_MAX_VISIBLE_PIECES];
  int pieces = 1;
  lo[0] = 0.0f;
  hi[0] = 1.0f;
  float3 me = cross(a, b);

  if (owner >= 0) { /* an occluder edge counts only inside S' */
    float t0 = 0.0f, t1 = 1.0f;
    for (int i = 0; i < st->ns; ++i) {
      float3 sa = st->sv[i], sb = st->sv[i + 1 == st->ns ? 0 : i + 1];
      float3 m = cross(sa, sb);
      if (degenerate_side(m, sa, sb)) continue; /* repeated S' vertex: no side plane */
      float f0 = -dot(m, a), f1 = -dot(m, b);
      /* In a boundary plane of S': same visible side → the source (lower index) keeps it;
       * opposite → dropped. Either way this occluder edge is not counted. */
      if (in_plane(m, a, b, f0, f1)) return 0.0f;
      clip_interval(f0, f1, &t0, &t1);
      if (!(t1 > t0)) return 0.0f;
    }
    lo[0] = t0;
    hi[0] = t1;
  }

  for (int v = 0; v < st->na; ++v) {
    if (v == owner) continue;
    PnOccluder o = occluders[st->active[v]];
    float t0 = 0.0f, t1 = 1.0f;
    bool covers = true;
    for (int e = 0; e < o.edgeCount && covers; ++e) {
      float3 ca, cb;
      if (!contour_edge(e, o, st->front[v], p, edges, overts, &ca, &cb)) continue;
      float3 m = cross(ca, cb);                 /* inside the occluder's cone: m·x > 0 */
      if (degenerate_side(m, ca, cb)) continue; /* P on the edge's line: no plane */
      float f0 = dot(m, a), f1 = dot(m, b);
      if (in_plane(m, a, b, f0, f1)) {
        bool same_side = dot(me, m) > 0.0f;
        if (same_side && owner < v) covers = false; /* this edge is the one kept */
        continue;                                   /* otherwise the plane does not limit */
      }
      clip_interval(f0, f1, &t0, &t1);
      if (!(t1 > t0)) covers = false;
    }
    if (!covers) continue;
    /* Subtract [t0, t1] from the sorted, disjoint visible pieces. */
    float nlo[PN_MAX_VISIBLE_PIECES], nhi[PN_MAX_VISIBLE_PIECES];
    int count = 0;
    for (int k = 0; k < pieces; ++k) {
      if (t1 <= lo[k] || t0 >= hi[k]) {
        nlo[count] = lo[k];
        nhi[count] = hi[k];
        ++count;
        continue;
      }
      if (t0 > lo[k]) {
        nlo[count] = lo[k];
        nhi[count] = t0;
        ++count;
      }
      if (t1 < hi[k]) {
        if (count == PN_MAX_VISIBLE_PIECES) {
          *error |= PN_ERROR_TOO_MANY_PIECES;
          break;
        }
        nlo[count] = t1;
        nhi[count] = hi[k];
        ++count;
      }
    }
    pieces = count;
    for (int k = 0; k < pieces; ++k) {
      lo[k] = nlo[k];
      hi[k] = nhi[k];
    }
    if (pieces == 0) return 0.0f;
  }

  float sum = 0.0f;
  float3 d = b - a;
  for (int k = 0; k < pieces; ++k) sum += edge_term(a + lo[k] * d, a + hi[k] * d, n);
  return sum;
}

float penumbra_face(float3 p, float3 n, int own, PnSourceFace face, __global const float4* vertices,
                    __global const PnOccluder* occluders, __global const float4* planes,
                    __global const int4* edges, __global const float4* overts, float eps_length,
                    int* error) {
  if (dot(face.plane.xyz, p) - face.plane.w <= 0.0f) return 0.0f;
  PenumbraState st;

  /* S': the face clipped by the horizon plane through P (Sutherland–Hodgman). */
  st.ns = 0;
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
  if (st.ns < 3) return 0.0f;

  /* One pass over the occluders: those with a face that sees P are candidates (unless their
   * bounding sphere misses the pyramid to the face); those with none are solids P lies on. */
  st.na = 0;
  int contacts = 0;
  for (int k = 0; k < face.occluderCount; ++k) {
    PnOccluder o = occluders[face.firstOccluder + k];
    if (o.solid == own || occluder_separated(p, o, planes, eps_length)) continue;
    ulong front = 0;
    for (int j = 0; j < o.planeCount; ++j) {
      float4 pl = planes[o.firstPlane + j];
      if (dot(pl.xyz, p) - pl.w > eps_length) front |= 1UL << j;
    }
    if (front == 0) {
      if (contacts == PN_MAX_CONTACTS) {
        *error |= PN_ERROR_TOO_MANY_CONTACTS;
        break;
      }
      ++contacts;
      if (!clip_by_contact(&st, p, n, o, planes, eps_length)) return 0.0f;
      continue;
    }
    if (sphere_outside_pyramid(p, n, o, face, vertices)) continue;
    if (st.na == PN_MAX_ACTIVE_OCCLUDERS) {
      *error |= PN_ERROR_TOO_MANY_OCCLUDERS;
      break;
    }
    st.active[st.na] = face.firstOccluder + k;
    st.front[st.na] = front;
    ++st.na;
  }

  float sum = 0.0f;
  for (int i = 0; i < st.ns; ++i)
    sum += visible_edge_term(st.sv[i], st.sv[i + 1 == st.ns ? 0 : i + 1], -1, n, p, &st, occluders,
                             edges, overts, error);
  for (int u = 0; u < st.na; ++u) {
    PnOccluder o = occluders[st.active[u]];
    for (int e = 0; e < o.edgeCount; ++e) {
      float3 ca, cb;
      if (!contour_edge(e, o, st.front[u], p, edges, overts, &ca, &cb)) continue;
      sum += visible_edge_term(ca, cb, u, n, p, &st, occluders, edges, overts, error);
    }
  }
  return sum;
}

/* ---------------------------------------------------------------------------------------------
 * The kernel: E (lx) at PN_LANES points per work-item, summed over every source face.
 * Points are structure-of-arrays, padded by the host to a multiple of PN_LANES. */

__kernel void illuminance(__global const float* px_, __global const float* py_,
                          __global const float* pz_, __global const float* nx_,
                          __global const float* ny_, __global const float* nz_,
                          __global const int* own_, __global const PnSourceFace* faces,
                          const int face_count, __global const float4* vertices,
                          __global const PnOccluder* occluders, __global const float4* planes,
                          __global const int4* edges, __global const float4* overts,
                          const float eps_length, __global float* out, __global int* errors) {
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

  float8 e_total = 0.0f;
  int error = 0;
  for (int f = 0; f < face_count; ++f) {
    PnSourceFace face = faces[f];
    float8 e_face = unoccluded_face8(px, py, pz, nx, ny, nz, face, vertices);

    /* Which lanes might be shaded: any occluder neither the point's own solid nor separated. */
    int8 shaded = 0;
    for (int k = 0; k < face.occluderCount; ++k) {
      PnOccluder o = occluders[face.firstOccluder + k];
      int8 culled = own == (int8)(o.solid);
      for (int j = 0; j < o.separatingCount; ++j) {
        float4 pl = planes[o.firstSeparating + j];
        culled |= (pl.x * px + pl.y * py + pl.z * pz - pl.w) >= -eps_length;
      }
      shaded |= ~culled;
    }
    if (any(shaded)) {
      float lane_e[PN_LANES];
      int lane_shaded[PN_LANES];
      vstore8(e_face, 0, lane_e);
      vstore8(shaded, 0, lane_shaded);
      for (int l = 0; l < PN_LANES; ++l) {
        if (!lane_shaded[l]) continue;
        float3 p = (float3)(lane_px[l], lane_py[l], lane_pz[l]);
        float3 n = (float3)(lane_nx[l], lane_ny[l], lane_nz[l]);
        lane_e[l] = penumbra_face(p, n, lane_own[l], face, vertices, occluders, planes, edges,
                                  overts, eps_length, &error);
      }
      e_face = vload8(0, lane_e);
    }
    e_total += face.halfLuminance * e_face;
  }
  vstore8(e_total, g, out);
  errors[g] = error;
}
