/* The penumbra path for one point: the visible region S' \ ∪ O_k (contour.cl) for one lane at a
 * time. The plain path (no culling) takes it for every shaded lane; with culling, the lanes the
 * eight-lane path (penumbra_lanes.cl) hands back: a solid touching P, an occluder with more faces
 * or a face with more vertices than it holds. */

#include "scalar_source.cl"

/* The side planes' ids: S' edges first, then the active occluders' contour edges. */
#define PN_ID_CONTOUR PN_MAX_SOURCE_POLYGON
inline float3 plane_of(const PenumbraState* st, int id) {
  return id < PN_ID_CONTOUR ? st->source_side[id] : st->contour_side[id - PN_ID_CONTOUR];
}

/* The boundary edge of plane id in the face's plane: an S' edge as it is (its ends are there), a
 * contour edge's ends through planar_end1 (each there where its ray meets the plane). */
inline PnPlanarLine1 planar_edge(const PenumbraState* st, int id) {
  PnPlanarLine1 line;
  line.a_in = line.b_in = 1;
  float3 a, b;
  if (id < PN_ID_CONTOUR) {
    a = st->source[id];
    b = st->source[id + 1 == st->source_count ? 0 : id + 1];
  } else {
    a = st->contour_a[id - PN_ID_CONTOUR];
    b = st->contour_b[id - PN_ID_CONTOUR];
  }
  line.ax = a.x, line.ay = a.y, line.az = a.z, line.bx = b.x, line.by = b.y, line.bz = b.z;
  if (id >= PN_ID_CONTOUR) {
    const int e = id - PN_ID_CONTOUR;
    const bool kept = planar_heights_kept(st->form.plane);
    const float na = kept ? st->contour_na[e] : plane_dot1(&st->form, a.x, a.y, a.z);
    const float nb = kept ? st->contour_nb[e] : plane_dot1(&st->form, b.x, b.y, b.z);
    line.a_in = planar_end1(&st->form, na, &line.ax, &line.ay, &line.az);
    line.b_in = planar_end1(&st->form, nb, &line.bx, &line.by, &line.bz);
  }
  return line;
}

/* The piece end p where the edges of planes self and other cross, as their lines' crossing in the
 * face's plane where the planar form serves (contour.cl, planar_crossing); *crossed says whether it
 * is. */
inline float3 planar_crossing_point(const PenumbraState* st, int self, int other, float3 p,
                                    int* crossed) {
  const PnPlanarLine1 first = planar_edge(st, min(self, other));
  const PnPlanarLine1 second = planar_edge(st, max(self, other));
  float x = p.x, y = p.y, z = p.z;
  *crossed = planar_crossing1(&st->form, &first, &second, 1, &x, &y, &z);
  return (float3)(x, y, z);
}

/* Whether an occluder edge of side normal m_self, lengths la and lb, whose ends lie at -f0 and -f1
 * along S' side plane i's normal, is tied to S' edge i (the tie rule, contour.cl): it lies in
 * that edge's side plane, and that edge in its own. */
inline bool tied_to_side(const PenumbraState* st, int i, float f0, float f1, float la, float lb,
                         float3 m_self) {
  const float3 c = st->source[i], d = st->source[i + 1 == st->source_count ? 0 : i + 1];
  return in_plane1(f0, f1, la, lb) &&
         edge_in_plane1(m_self.x, m_self.y, m_self.z, c.x, c.y, c.z, d.x, d.y, d.z);
}

/* Integral over the visible parts of one boundary edge owned by region `owner` (-1 = source),
 * whose side plane has id `self` (its unit normal is plane_of(st, self)). Where the face is small,
 * oa and ob are its ends' offsets from the face's centre when `exact` (source_offset), else
 * unused. */
void visible_edge_term(float3 a, float3 b, float3 oa, float3 ob, bool exact, int owner, int self,
                       float3 n, PenumbraState* st, int* error, PnSum* acc) {
  const float3 m_self = plane_of(st, self);
  if (no_plane(m_self)) return; /* its line passes through P: no solid angle */
  float lo[PN_MAX_VISIBLE_PIECES], hi[PN_MAX_VISIBLE_PIECES];
  int lo_id[PN_MAX_VISIBLE_PIECES], hi_id[PN_MAX_VISIBLE_PIECES];
  int pieces = 1;
  lo[0] = 0.0f;
  hi[0] = 1.0f;
  lo_id[0] = hi_id[0] = PN_ID_VERTEX;
  const float la = sqrt(pn_dot(a, a)), lb = sqrt(pn_dot(b, b));

  if (owner >= 0) { /* an occluder edge counts only inside S' */
    float t0 = 0.0f, t1 = 1.0f;
    for (int i = 0; i < st->source_count; ++i) {
      float3 m = st->source_side[i];
      if (no_plane(m)) continue; /* repeated S' vertex: no side plane */
      float f0 = -pn_dot(m, a), f1 = -pn_dot(m, b);
      /* In a boundary plane of S' whose edge lies in this edge's plane: same visible side → the
       * source (lower index) keeps it; opposite → dropped. Either way this occluder edge is not
       * counted. */
      if (tied_to_side(st, i, f0, f1, la, lb, m_self)) {
        st->tie_seen = true;
        return;
      }
      if (!clip_interval_id1(f0, f1, 1, i, &t0, &t1, &lo_id[0], &hi_id[0])) return;
    }
    lo[0] = t0;
    hi[0] = t1;
  }

  for (int v = 0; v < st->active_count; ++v) {
    if (v == owner) continue;
    float t0 = 0.0f, t1 = 1.0f;
    int id0 = PN_ID_VERTEX, id1 = PN_ID_VERTEX;
    bool covers = true;
    for (int e = st->first_contour[v]; e < st->first_contour[v + 1] && covers; ++e) {
      float3 m = st->contour_side[e]; /* inside the occluder's cone: m·x > 0 */
      if (no_plane(m)) continue;      /* P on the edge's line */
      float f0 = pn_dot(m, a), f1 = pn_dot(m, b);
      const float3 c = st->contour_a[e], d = st->contour_b[e];
      if (in_plane1(f0, f1, la, lb) &&
          edge_in_plane1(m_self.x, m_self.y, m_self.z, c.x, c.y, c.z, d.x, d.y, d.z)) {
        if (keeps_tied_edge1(1, m_self.x, m_self.y, m_self.z, m.x, m.y, m.z, owner, v))
          covers = false;
        continue;
      }
      if (!clip_interval_id1(f0, f1, 1, PN_ID_CONTOUR + e, &t0, &t1, &id0, &id1)) covers = false;
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
    int turned0 = 0, turned1 = 0;
    if (lo_id[k] != PN_ID_VERTEX)
      p0 = crossing_point(m_self, self, plane_of(st, lo_id[k]), lo_id[k], p0, &turned0);
    if (hi_id[k] != PN_ID_VERTEX)
      p1 = crossing_point(m_self, self, plane_of(st, hi_id[k]), hi_id[k], p1, &turned1);
    /* In the planar form the turned ends are the edges' crossing in the plane. */
    int crossed0 = 0, crossed1 = 0;
    if (st->form.crossing_lanes && turned0)
      p0 = planar_crossing_point(st, self, lo_id[k], p0, &crossed0);
    if (st->form.crossing_lanes && turned1)
      p1 = planar_crossing_point(st, self, hi_id[k], p1, &crossed1);
    float3 o0 = 0.0f, o1 = 0.0f;
    if (st->form.small) {
      o0 = exact && !turned0 ? edge_point(oa, ob, lo[k]) : centre_offset(&st->form, p0);
      o1 = exact && !turned1 ? edge_point(oa, ob, hi[k]) : centre_offset(&st->form, p1);
    }
    /* An occluder's piece is off the face's plane; so are turned ends, but for the crossings found
     * in it. */
    const int off0 = (owner >= 0 || turned0) && !crossed0;
    const int off1 = (owner >= 0 || turned1) && !crossed1;
    /* N·p at each end: from the occluder's vertices' heights along its edge, but at turned ends. */
    float np0 = plane_dot1(&st->form, p0.x, p0.y, p0.z);
    float np1 = plane_dot1(&st->form, p1.x, p1.y, p1.z);
    if (owner >= 0 && st->form.planar_lanes && planar_heights_kept(st->form.plane)) {
      const int e = self - PN_ID_CONTOUR;
      if (!turned0) np0 = edge_point1(st->contour_na[e], st->contour_nb[e], lo[k]);
      if (!turned1) np1 = edge_point1(st->contour_na[e], st->contour_nb[e], hi[k]);
    }
    pn_sum_add(acc, form_piece_term(&st->form, p0, p1, o0, o1, n, off0, off1, np0, np1));
  }
}

/* Moves the vertices of the contour edges tied to an S' edge into that edge's side plane, at
 * every contour edge that ends there (snap_end, contour.cl), and takes their side planes anew. */
#define PN_MAX_TIED_ENDS 8
void snap_tied_vertices(PenumbraState* st) {
  float3 vertex[PN_MAX_TIED_ENDS];
  int plane[PN_MAX_TIED_ENDS];
  int count = 0;
  const int edges = st->first_contour[st->active_count];
  for (int e = 0; e < edges; ++e) {
    const float3 a = st->contour_a[e], b = st->contour_b[e], m_self = st->contour_side[e];
    if (no_plane(m_self)) continue;
    const float la = sqrt(pn_dot(a, a)), lb = sqrt(pn_dot(b, b));
    for (int i = 0; i < st->source_count && count + 2 <= PN_MAX_TIED_ENDS; ++i) {
      const float3 m = st->source_side[i];
      if (no_plane(m) || !tied_to_side(st, i, -pn_dot(m, a), -pn_dot(m, b), la, lb, m_self))
        continue;
      vertex[count] = a;
      plane[count++] = i;
      vertex[count] = b;
      plane[count++] = i;
    }
  }
  for (int e = 0; e < edges && count > 0; ++e) {
    const float3 a0 = st->contour_a[e], b0 = st->contour_b[e];
    float ax = a0.x, ay = a0.y, az = a0.z, bx = b0.x, by = b0.y, bz = b0.z;
    bool moved = false;
    for (int k = 0; k < count; ++k) {
      const int i = plane[k], j = i + 1 == st->source_count ? 0 : i + 1;
      const float3 m = st->source_side[i], c = st->source[i], d = st->source[j];
      const float3 v = vertex[k];
      const int at_a = a0.x == v.x && a0.y == v.y && a0.z == v.z;
      const int at_b = b0.x == v.x && b0.y == v.y && b0.z == v.z;
      if (!at_a && !at_b) continue;
      float ux, uy, uz;
      edge_across1(st->form.plane.xyz, c.x, c.y, c.z, d.x, d.y, d.z, &ux, &uy, &uz);
      snap_end1(m.x, m.y, m.z, ux, uy, uz, at_a, &ax, &ay, &az);
      snap_end1(m.x, m.y, m.z, ux, uy, uz, at_b, &bx, &by, &bz);
      moved = true;
    }
    if (!moved) continue;
    st->contour_a[e] = (float3)(ax, ay, az);
    st->contour_b[e] = (float3)(bx, by, bz);
    /* the ends' heights move with them (snap_tied_vertices8) */
    st->contour_na[e] += plane_dot1(&st->form, ax - a0.x, ay - a0.y, az - a0.z);
    st->contour_nb[e] += plane_dot1(&st->form, bx - b0.x, by - b0.y, bz - b0.z);
    st->contour_side[e] = side_normal(st->contour_a[e], st->contour_b[e]);
  }
}

/* The sum over the visible contour; sets st->tie_seen where an occluder's edge is tied to an S'
 * edge. */
float contour_sum(PenumbraState* st, float3 n, int* error) {
  st->tie_seen = false;
  st->planar.dpsi_sum = 0.0f;
  PnSum sum = {0.0f, 0.0f};
  for (int i = 0; i < st->source_count; ++i) {
    const int j = i + 1 == st->source_count ? 0 : i + 1;
    visible_edge_term(st->source[i], st->source[j], st->source_offset[i], st->source_offset[j],
                      st->source_exact[i] && st->source_exact[j], -1, i, n, st, error, &sum);
  }
  for (int u = 0; u < st->active_count; ++u)
    for (int e = st->first_contour[u]; e < st->first_contour[u + 1]; ++e)
      visible_edge_term(st->contour_a[e], st->contour_b[e], 0.0f, 0.0f, false, u, PN_ID_CONTOUR + e,
                        n, st, error, &sum);
  if (!st->form.planar_lanes) return sum.s + sum.c;
  return (sum.s + sum.c) + planar_closing1(&st->planar, &st->emission);
}

/* E / (L/2) of the visible part of S' (st->source) past the active occluders. Where an occluder's
 * edge is tied to an S' edge (rare), its vertices are moved into that edge's side plane and the
 * sum taken again. */
float region_sum(PenumbraState* st, float3 n, int* error) {
  for (int i = 0; i < st->source_count; ++i)
    st->source_side[i] =
        side_normal(st->source[i], st->source[i + 1 == st->source_count ? 0 : i + 1]);
  const float sum = contour_sum(st, n, error);
  if (!st->tie_seen) return sum;
  snap_tied_vertices(st);
  return contour_sum(st, n, error);
}

/* S' minus the wedges of the solids P lies on the edge or corner of (contact_faces), as disjoint
 * convex pieces: for a wedge of faces f_1 … f_m the part of a piece outside the wedge is the
 * union over i of {f_i·x ≥ 0, f_j·x < 0 for j < i}; every piece is integrated like S' (the tie
 * rule holds for any convex region) and the pieces' shared sides cancel in the sum. */
float wedge_pieces_sum(PenumbraState* st, float3 n, const float3 (*wedge)[PN_MAX_WEDGE_FACES],
                       const int* wedge_faces, int wedges, int* error) {
  float3 base[PN_MAX_SOURCE_POLYGON], base_offset[PN_MAX_SOURCE_POLYGON];
  int base_exact[PN_MAX_SOURCE_POLYGON];
  const int base_count = st->source_count;
  for (int i = 0; i < base_count; ++i) {
    base[i] = st->source[i];
    base_offset[i] = st->source_offset[i];
    base_exact[i] = st->source_exact[i];
  }
  int pieces = 1;
  for (int k = 0; k < wedges; ++k) pieces *= wedge_faces[k];
  PnSum sum = {0.0f, 0.0f};
  for (int piece = 0; piece < pieces; ++piece) {
    st->source_count = base_count;
    for (int i = 0; i < base_count; ++i) {
      st->source[i] = base[i];
      st->source_offset[i] = base_offset[i];
      st->source_exact[i] = base_exact[i];
    }
    int code = piece;
    for (int k = 0; k < wedges && st->source_count >= 3; ++k) {
      const int chosen = code % wedge_faces[k];
      code /= wedge_faces[k];
      for (int j = 0; j < chosen && st->source_count >= 3; ++j) clip_source(st, -wedge[k][j]);
      if (st->source_count >= 3) clip_source(st, wedge[k][chosen]);
    }
    if (st->source_count >= 3) pn_sum_add(&sum, region_sum(st, n, error));
  }
  return sum.s + sum.c;
}

/* S' for P (p, p_lo: PnPosition): the face (or, `aperture`, the visible rectangle in `corners`)
 * clipped by the horizon plane through P (Sutherland–Hodgman), with its side normals. False where
 * P sees nothing of it. */
bool source_polygon(PenumbraState* st, float3 p, float3 p_lo, float3 n, PnSourceFace face,
                    const PnSceneTables* tables, bool aperture, const float3* corners) {
  st->source_count = 0;
  st->emission = emission_of(face, tables);
  st->form.em = &st->emission;
  int k = 0;
  st->form.small = small_face1(p, p_lo, face, tables, &st->form.centre, &k);
  st->form.plane = face.plane;
  st->form.height = 0.0f;
  if (st->form.small)
    st->form.height =
        pn_dot(face.plane.xyz, (float3)(st->form.centre.x, st->form.centre.y, st->form.centre.z));
  /* The planar form where P sees the face near its plane, as the lanes take it. */
  const float3 v0 = pn_from1(tables->sourceVertices[face.firstVertex], p, p_lo);
  st->form.planar = &st->planar;
  st->form.planar_lanes =
      !st->form.small && planar_lanes1(face, &st->emission, v0.x, v0.y, v0.z, false);
  st->form.crossing_lanes =
      !st->form.small && planar_lanes1(face, &st->emission, v0.x, v0.y, v0.z, true);
  if (st->form.crossing_lanes)
    st->planar =
        planar_frame_at1(p.x, p.y, p.z, p_lo.x, p_lo.y, p_lo.z, n.x, n.y, n.z, face, tables);
  if (aperture) {
    for (int i = 0; i < 4; ++i) {
      st->source[i] = corners[i];
      st->source_offset[i] = 0.0f;
      st->source_exact[i] = 0; /* offsets from the vectors from P */
    }
    st->source_count = 4;
    clip_source(st, n);
  } else {
    const int m = face.vertexCount;
    float3 a = pn_from1(tables->sourceVertices[face.firstVertex], p, p_lo);
    float3 oa = st->form.small ? vertex_offset(face, 0, k, tables) : 0.0f;
    float ha = dot(n, a);
    for (int i = 0; i < m; ++i) {
      const int j = i + 1 == m ? 0 : i + 1;
      float3 b = pn_from1(tables->sourceVertices[face.firstVertex + j], p, p_lo);
      float3 ob = st->form.small ? vertex_offset(face, j, k, tables) : 0.0f;
      float hb = dot(n, b);
      if (ha >= 0.0f) {
        st->source[st->source_count] = a;
        st->source_offset[st->source_count] = oa;
        st->source_exact[st->source_count++] = 1;
      }
      if ((ha >= 0.0f) != (hb >= 0.0f)) {
        const float t = ha / (ha - hb);
        st->source[st->source_count] = a + t * (b - a);
        st->source_offset[st->source_count] = oa + t * (ob - oa);
        st->source_exact[st->source_count++] = 1;
      }
      a = b;
      oa = ob;
      ha = hb;
    }
  }
  if (st->source_count < 3) return false;
  /* A face seen edge-on (every vertex of S' within the tolerance of the horizon, e.g. a source
   * corner exactly in P's tangent plane) gives nothing: its E is below PN_EPS_REL · π·L, and the
   * side planes of such a sliver have no direction, so occluder edges would be taken as inside it
   * and integrated as holes (bench/degenerate_stress has such points: E = -11 lx without this). */
  float rise = 0.0f;
  for (int i = 0; i < st->source_count; ++i)
    rise = fmax(rise, dot(n, st->source[i]) / length(st->source[i]));
  if (rise <= PN_EPS_REL) return false;

  for (int i = 0; i < st->source_count; ++i)
    st->source_side[i] =
        side_normal(st->source[i], st->source[i + 1 == st->source_count ? 0 : i + 1]);
  return true;
}

/* Adds occluder o, active at P, with its contour edges. */
void add_contour(PenumbraState* st, PnOccluder o, PnSourceFace face, float3 p, float3 p_lo,
                 const PnSceneTables* tables, float eps_length, int* error) {
  int c = st->first_contour[st->active_count];
  for (int e = 0; e < o.edgeCount; ++e) {
    float3 ea, eb;
    PnPosition qa, qb;
    if (!contour_edge(e, o, p, p_lo, tables, eps_length, &ea, &eb, &qa, &qb)) continue;
    if (c == PN_MAX_CONTOUR_EDGES) {
      *error |= PN_ERROR_TOO_MANY_CONTOUR_EDGES;
      break;
    }
    st->contour_a[c] = ea;
    st->contour_b[c] = eb;
    st->contour_side[c] = side_normal(ea, eb);
    st->contour_na[c] = st->contour_nb[c] = 0.0f;
    if (st->form.crossing_lanes && planar_heights_kept(face.plane)) {
      st->contour_na[c] = planar_depth1(qa, ea.x, ea.y, ea.z, face, &st->planar, tables);
      st->contour_nb[c] = planar_depth1(qb, eb.x, eb.y, eb.z, face, &st->planar, tables);
    }
    ++c;
  }
  ++st->active_count;
  st->first_contour[st->active_count] = c;
}

/* P's position is p + p_lo (PnPosition: plane tests read p). `aperture`: P sees the face through
 * its aperture (host/shadow/aperture.hpp); `corners` then holds the visible rectangle relative to
 * P, and occluders behind the aperture are skipped. */
float penumbra_face(float3 p, float3 p_lo, float3 n, int own, PnSourceFace face, PnPatchFace pf,
                    bool culling, const PnSceneTables* tables, float eps_length, bool aperture,
                    const float3* corners, int* error) {
  PenumbraState st;
  if (!in_front1(face, p.x, p.y, p.z) ||
      !source_polygon(&st, p, p_lo, n, face, tables, aperture, corners))
    return 0.0f;

  /* One pass over the patch's occluders: those with a face that sees P are candidates (unless
   * P is outside their penumbra volume or they miss the pyramid to S'); those with none are
   * solids P lies on. */
  st.active_count = 0;
  st.first_contour[0] = 0;
  int contacts = 0;
  float3 wedge[PN_MAX_WEDGES][PN_MAX_WEDGE_FACES];
  int wedge_faces[PN_MAX_WEDGES];
  int wedges = 0;
  const int count = occluder_count(pf, face);
  for (int i = 0; i < count; ++i) {
    PnOccluder o = tables->occluders[occluder_index(i, pf, face, tables)];
    if (aperture && o.behindAperture) continue;
    if (o.solid == own || !not_separated1(o, tables, p.x, p.y, p.z, eps_length, 1)) continue;
    if (culling && !in_penumbra_volume1(o, tables, p.x, p.y, p.z, eps_length, 1)) continue;
    bool any_front = false;
    for (int j = 0; j < o.planeCount && !any_front; ++j)
      any_front = face_sees1(o, j, tables, p.x, p.y, p.z, eps_length);
    if (!any_front) {
      if (contacts == PN_MAX_CONTACTS) {
        *error |= PN_ERROR_TOO_MANY_CONTACTS;
        break;
      }
      ++contacts;
      float3 limiting[PN_MAX_WEDGE_FACES], opposed;
      const int m =
          contact_faces(&st, p, n, o, tables, eps_length, limiting, PN_MAX_WEDGE_FACES, &opposed);
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
      if (st.source_count < 3) return 0.0f;
      for (int i = 0; i < st.source_count; ++i)
        st.source_side[i] =
            side_normal(st.source[i], st.source[i + 1 == st.source_count ? 0 : i + 1]);
      continue;
    }
    if (culling ? outside_source_pyramid(&st, p, n, o, aperture, tables, eps_length)
                : sphere_outside_pyramid(p, n, o, face, tables))
      continue;
    if (st.active_count == PN_MAX_ACTIVE_OCCLUDERS) {
      *error |= PN_ERROR_TOO_MANY_OCCLUDERS;
      break;
    }
    add_contour(&st, o, face, p, p_lo, tables, eps_length, error);
  }

  const float sum = wedges == 0 ? region_sum(&st, n, error)
                                : wedge_pieces_sum(&st, n, wedge, wedge_faces, wedges, error);
  /* A visible region gives no negative light: a sum below 0 is the float round-off of an empty
   * one (an umbra's edge: -5e-6 lx where π·L = 3142 lx, bench/degenerate_stress). */
  return fmax(sum, 0.0f);
}
