/* The scalar penumbra path's state (PenumbraState: S' and the active occluders' contour edges,
 * for one point) and what shapes S' and picks its occluders before the contour is integrated
 * (penumbra_scalar.cl): the clip of S' by a plane through P, the faces of a solid P lies on,
 * and the two tests of an occluder's bounding sphere against the pyramid P + S'. */

#include "contour.cl"
#include "occluders.cl"

/* S' vertices, relative to P: each clip by a plane through P adds at most one vertex (the
 * horizon, a contact's face, a wedge piece's faces). */
#define PN_MAX_SOURCE_POLYGON \
  (PN_MAX_SOURCE_VERTICES + 1 + PN_MAX_CONTACTS + PN_MAX_WEDGES * PN_MAX_WEDGE_FACES)

typedef struct {
  float3 source[PN_MAX_SOURCE_POLYGON];      /* S', relative to P */
  float3 source_side[PN_MAX_SOURCE_POLYGON]; /* its unit side normals */
  /* Where the face is small (form.small): each S' vertex's offset from form.centre (contour.cl,
   * PnPieceForm), exact (a vertex of the face or an interpolation of two exact ones) or not (to
   * be taken from the vector from P: centre_offset). */
  float3 source_offset[PN_MAX_SOURCE_POLYGON];
  int source_exact[PN_MAX_SOURCE_POLYGON];
  int source_count;
  /* The active occluders' contour edges, hole-oriented, relative to P, with their unit side-plane
   * normals along cross(a, b) (zero where P is on the edge's line: no plane), extracted once per
   * point: occluder v owns edges [first_contour[v], first_contour[v + 1]). */
  float3 contour_a[PN_MAX_CONTOUR_EDGES], contour_b[PN_MAX_CONTOUR_EDGES];
  float3 contour_side[PN_MAX_CONTOUR_EDGES];
  /* N·a and N·b for the face's plane (planar_depth1), where form.crossing_lanes is set and
   * planar_heights_kept */
  float contour_na[PN_MAX_CONTOUR_EDGES], contour_nb[PN_MAX_CONTOUR_EDGES];
  int first_contour[PN_MAX_ACTIVE_OCCLUDERS + 1];
  int active_count;
  PnEmission emission;   /* how the face emits (luminance_moments.cl) */
  PnPieceForm1 form;     /* how its pieces are integrated (contour.cl), reading `emission` */
  PnPlanarFrame1 planar; /* the face's planar frame, where form.crossing_lanes is set */
  bool tie_seen;         /* an occluder's edge was tied to an S' edge (contour_sum) */
} PenumbraState;

/* Keeps the part of S' with keep·x >= 0 (a plane through P; Sutherland–Hodgman). */
void clip_source(PenumbraState* st, float3 keep) {
  float3 out[PN_MAX_SOURCE_POLYGON], out_offset[PN_MAX_SOURCE_POLYGON];
  int out_exact[PN_MAX_SOURCE_POLYGON];
  int count = 0;
  int last = st->source_count - 1;
  float3 a = st->source[last];
  float ha = dot(keep, a);
  for (int i = 0; i < st->source_count; ++i) {
    float3 b = st->source[i];
    float hb = dot(keep, b);
    if ((ha >= 0.0f) != (hb >= 0.0f)) {
      const float t = ha / (ha - hb);
      out[count] = a + t * (b - a);
      out_exact[count] = st->source_exact[last] && st->source_exact[i];
      out_offset[count] =
          st->source_offset[last] + t * (st->source_offset[i] - st->source_offset[last]);
      ++count;
    }
    if (hb >= 0.0f) {
      out[count] = b;
      out_exact[count] = st->source_exact[i];
      out_offset[count++] = st->source_offset[i];
    }
    a = b;
    ha = hb;
    last = i;
  }
  for (int i = 0; i < count; ++i) {
    st->source[i] = out[i];
    st->source_offset[i] = out_offset[i];
    st->source_exact[i] = out_exact[i];
  }
  st->source_count = count;
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
                  const PnSceneTables* tables, float eps_length, float3* limiting, int capacity,
                  float3* opposed) {
  int count = -1;
  float most = 2.0f;
  for (int j = 0; j < o.planeCount; ++j) {
    float4 pl = tables->planes[o.firstPlane + j];
    if (plane_height1(pl, p.x, p.y, p.z) < -eps_length) continue; /* not through P */
    if (count < 0) count = 0;
    bool holds_source = true;
    for (int i = 0; i < st->source_count && holds_source; ++i)
      holds_source = dot(pl.xyz, st->source[i]) <= PN_EPS_REL * length(st->source[i]);
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

/* The plain path's test: the bounding sphere against the pyramid P + cone(face), the whole face
 * (the plain path has no S' side planes before its occluder pass). */
inline bool sphere_outside_pyramid(float3 p, float3 n, PnOccluder o, PnSourceFace face,
                                   const PnSceneTables* tables) {
  float3 c = o.bound.xyz - p;
  float r = o.bound.w;
  if (dot(n, c) < -r) return true;
  const int m = face.vertexCount;
  float3 a = tables->sourceVertices[face.firstVertex].hi.xyz - p;
  for (int i = 0; i < m; ++i) {
    float3 b = tables->sourceVertices[face.firstVertex + (i + 1 == m ? 0 : i + 1)].hi.xyz - p;
    /* inside the pyramid: cross(a, b)·x < 0 for every side (see the orientation note below) */
    float3 side = cross(a, b);
    if (dot(side, c) > r * length(side)) return true;
    a = b;
  }
  return false;
}

/* Whether an occluder misses the pyramid P + cone(S') (S' side normals in st->source_side): its
 * bounding sphere is below the horizon or outside a side plane; or, for a lane that sees the face
 * through an aperture (where the occluder's volume is the whole face's, not S''s), all its vertices
 * are outside a side plane by more than eps_length. */
bool outside_source_pyramid(const PenumbraState* st, float3 p, float3 n, PnOccluder o,
                            bool vertices, const PnSceneTables* tables, float eps_length) {
  float3 c = o.bound.xyz - p;
  float r = o.bound.w;
  if (dot(n, c) < -r) return true;
  for (int i = 0; i < st->source_count; ++i)
    if (dot(st->source_side[i], c) > r) return true; /* (a zero normal never passes) */
  if (!vertices) return false;
  for (int i = 0; i < st->source_count; ++i) {
    float3 m = st->source_side[i]; /* a zero normal (no plane) never has the vertices outside */
    bool out = true;
    for (int k = 0; k < o.vertexCount && out; ++k)
      out = dot(m, tables->occluderVertices[o.firstVertex + k].hi.xyz - p) > eps_length;
    if (out) return true;
  }
  return false;
}
