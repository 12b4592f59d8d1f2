/* The penumbra path in eight lanes (culling only; the plain path takes penumbra_scalar.cl).
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
 * lanes alone, and gives them to the scalar path when that does not help.
 *
 * Here: the lane-parallel contour store and the visible parts of one edge; the face itself is
 * penumbra_lanes.cl. */

#include "contour.cl"

#define PN_VEC_OCCLUDERS 32 /* active occluders per work-item and face */
#define PN_VEC_EDGES 192    /* their edges in all */
#define PN_VEC_FACES 16     /* faces of one occluder */
#define PN_VEC_SOURCE 8     /* vertices of the face */
#define PN_VEC_PASSES 4     /* calls per work-item and face, each on the lanes the last left */

/* An active occluder's edge in two parts: its side plane, which every other region's edges are
 * tested against (the hot loop of visible_edge_term8, so kept compact), and its ends. */
typedef struct {
  float8 mx, my, mz; /* unit side-plane normal along cross(a, b); 0: none */
  int8 on;           /* lanes where it is a contour edge with a side plane */
} EdgePlane8;

typedef struct {
  float8 ax, ay, az, bx, by, bz; /* hole-oriented per lane, relative to P */
  int8 on;                       /* lanes where it is a contour edge of the occluder */
  /* N·a and N·b for the face's plane (planar_depth8), in its crossing lanes where
   * planar_heights_kept */
  float8 na, nb;
} ContourEdge8;

/* The cone of directions from P to an occluder's bounding sphere: unit axis u and the sine and
 * cosine of its half-angle, grown by PN_VEC_CONE_MARGIN (2 and -2 where P is inside the
 * sphere). An edge whose great circle, or whose arc, stays outside it cannot be covered by the
 * occluder, which visible_edge_term8 then skips without walking its side planes. */
typedef struct {
  float8 ux, uy, uz, sin_a, cos_a;
} BoundCone8;

#define PN_VEC_CONE_MARGIN 1e-3f

/* The active occluders of one call of penumbra_face8, in candidate order, and their contour
 * edges: occluder v owns edges [first_edge[v], first_edge[v + 1]). */
typedef struct {
  EdgePlane8 plane[PN_VEC_EDGES];
  ContourEdge8 edge[PN_VEC_EDGES];
  BoundCone8 cone[PN_VEC_OCCLUDERS];
  int8 lanes[PN_VEC_OCCLUDERS];   /* the lanes each occluder is active in */
  int8 whole[PN_VEC_OCCLUDERS];   /* lanes where each of its contour edges has a side plane */
  int occluder[PN_VEC_OCCLUDERS]; /* its index among the occluders */
  int first_edge[PN_VEC_OCCLUDERS + 1];
  int count;
} Contours8;

/* A piece end per lane where another region's side plane set it: the cross product of the two
 * unit side normals, in the order of their plane ids (crossing_point says why). */
typedef struct {
  float8 x, y, z;
  int8 set;
  int8 id; /* the other plane's id, where set */
} PieceEnd8;

inline void piece_end_clear8(PieceEnd8* e) {
  e->x = e->y = e->z = 0.0f;
  e->set = 0;
  e->id = -1;
}

/* The side planes' ids in eight lanes: S' edges 0 … m − 1, the chord m, then the contour store. */
#define PN_VEC_ID_CONTOUR (PN_VEC_SOURCE + 1)

/* Once an interval is known to matter: the crossing points at its ends (id0, id1 from
 * clip_interval_id8: the index of the plane that set each end, -1 for none), each the
 * crossing_direction8 of the edge's unit side normal ms (plane id `self`) and that plane's. Plane
 * k's normal is planes[k] and its id first_id + k. Done after the clipping, for the intervals that
 * are kept, and once per distinct plane among the lanes (usually one or two) rather than at every
 * plane that moves an end. */
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
    float8 dx, dy, dz;
    crossing_direction8(msx, msy, msz, self, c->mx, c->my, c->mz, id, &dx, &dy, &dz);
    e0->x = select(e0->x, dx, at0);
    e0->y = select(e0->y, dy, at0);
    e0->z = select(e0->z, dz, at0);
    e0->set |= at0;
    e0->id = select(e0->id, (int8)(id), at0);
    e1->x = select(e1->x, dx, at1);
    e1->y = select(e1->y, dy, at1);
    e1->z = select(e1->z, dz, at1);
    e1->set |= at1;
    e1->id = select(e1->id, (int8)(id), at1);
    left0 &= ~at0;
    left1 &= ~at1;
  }
}

/* S' as planar_crossing8 reads its edges: edge i < m from vertex i to i + 1, edge m the horizon
 * chord (penumbra_lanes.cl's SourcePolygon8). */
typedef struct {
  const float8 *x, *y, *z;
  const HorizonChord8* chord;
  int m;
} SourceRing8;

/* The boundary edge of plane id in the face's plane: an S' edge as it is (its ends are there), a
 * contour edge's ends through planar_end8 (each there in the lanes where its ray meets the
 * plane). */
inline void planar_edge8(const PnPieceForm8* form, const SourceRing8* ring, const Contours8* cs,
                         int id, PnPlanarLine8* line) {
  if (id >= PN_VEC_ID_CONTOUR) {
    const ContourEdge8* e = &cs->edge[id - PN_VEC_ID_CONTOUR];
    line->ax = e->ax, line->ay = e->ay, line->az = e->az;
    line->bx = e->bx, line->by = e->by, line->bz = e->bz;
    const bool kept = planar_heights_kept(form->plane);
    const float8 na = kept ? e->na : plane_dot8(form, e->ax, e->ay, e->az);
    const float8 nb = kept ? e->nb : plane_dot8(form, e->bx, e->by, e->bz);
    line->a_in = planar_end8(form, na, &line->ax, &line->ay, &line->az);
    line->b_in = planar_end8(form, nb, &line->bx, &line->by, &line->bz);
    return;
  }
  if (id == ring->m) {
    line->ax = ring->chord->exit_x, line->ay = ring->chord->exit_y, line->az = ring->chord->exit_z;
    line->bx = ring->chord->entry_x, line->by = ring->chord->entry_y;
    line->bz = ring->chord->entry_z;
  } else {
    const int j = id + 1 == ring->m ? 0 : id + 1;
    line->ax = ring->x[id], line->ay = ring->y[id], line->az = ring->z[id];
    line->bx = ring->x[j], line->by = ring->y[j], line->bz = ring->z[j];
  }
  line->a_in = line->b_in = -1;
}

/* In the lanes of `use`, the piece end p where the edge of plane id `self` meets the edge of plane
 * end->id, as their lines' crossing in the face's plane (planar_crossing8), once per distinct
 * other plane among the lanes. Returns the lanes whose end it set. */
inline int8 planar_crossings8(const PnPieceForm8* form, const SourceRing8* ring,
                              const Contours8* cs, int self, const PieceEnd8* end, int8 use,
                              float8* px, float8* py, float8* pz) {
  int8 done = 0;
  int8 left = use & (end->id >= 0);
  while (pn_any(left)) {
    const int other = __builtin_reduce_min(select((int8)(INT_MAX), end->id, left));
    const int8 at = left & (end->id == other);
    left &= ~at;
    PnPlanarLine8 first, second;
    planar_edge8(form, ring, cs, min(self, other), &first);
    planar_edge8(form, ring, cs, max(self, other), &second);
    done |= planar_crossing8(form, &first, &second, at, px, py, pz);
  }
  return done;
}

/* A boundary edge of the visible region, as visible_edge_term8 integrates it. */
typedef struct {
  float8 ax, ay, az, bx, by, bz; /* its ends, from P */
  const EdgePlane8* side;        /* its side plane */
  int self;                      /* that plane's id */
  int owner;                     /* the region it bounds: an occluder's index, -1 for S' */
  /* An edge of S' where the face is small: its ends' offsets from the face's centre, exact in the
   * lanes of offsets->on (contour.cl, PnPieceForm); null for an occluder's edge. */
  const ContourEdge8* offsets;
  /* An occluder's contour edge, whose ends' heights planar_point reads; null for an edge of S'. */
  const ContourEdge8* occluder;
} BoundaryEdge8;

/* The part of a boundary edge to integrate: the parameter range [lo, hi] of the lanes in `on`,
 * and the crossings its ends are at (set where the range was cut by a side plane). */
typedef struct {
  float8 lo, hi;
  const PieceEnd8* lo_end;
  const PieceEnd8* hi_end;
  int8 on;
} EdgeSpan8;

/* What every boundary edge of one face's visible region is integrated against: how its pieces
 * are integrated, the occluders' contours, S' and the points' normals. */
typedef struct {
  const PnPieceForm8* form;
  const Contours8* cs;
  const SourceRing8* ring;
  float8 nx, ny, nz;
} ContourContext8;

/* Integral over the visible parts of the boundary edge e within its span (per lane). Inlined at
 * its three call sites, where the structs' fields stay in registers: called, it read them through
 * memory (illuminance_bench --points 1024: 4.94 M kernel instructions against 4.78 M inlined;
 * the kernel's compile takes 0.8 s more, once per PoCL cache). */
__attribute__((always_inline)) inline void visible_edge_term8(const BoundaryEdge8* e,
                                                              const EdgeSpan8* span,
                                                              const ContourContext8* ctx,
                                                              PnSum8* acc) {
  const float8 ax = e->ax, ay = e->ay, az = e->az, bx = e->bx, by = e->by, bz = e->bz;
  const float8 msx = e->side->mx, msy = e->side->my, msz = e->side->mz;
  const int self = e->self, owner = e->owner;
  const ContourEdge8 *offsets = e->offsets, *edge = e->occluder;
  const float8 lo = span->lo, hi = span->hi;
  const PieceEnd8 *lo_end = span->lo_end, *hi_end = span->hi_end;
  const int8 on = span->on;
  const PnPieceForm8* form = ctx->form;
  const Contours8* cs = ctx->cs;
  const SourceRing8* ring = ctx->ring;
  const float8 nx = ctx->nx, ny = ctx->ny, nz = ctx->nz;
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
  for (int v = 0; v < cs->count; ++v) {
    float8 t0 = 0.0f, t1 = 1.0f;
    int8 id0 = -1, id1 = -1;
    int8 covers = v == owner ? (int8)(0) : on & cs->lanes[v];
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
      const BoundCone8* cone = &cs->cone[v];
      float8 d = cone->ux * gx + cone->uy * gy + cone->uz * gz;
      float8 ea = cone->ux * aux + cone->uy * auy + cone->uz * auz;
      float8 eb = cone->ux * bux + cone->uy * buy + cone->uz * buz;
      int8 inside_arc = (cone->ux * tax + cone->uy * tay + cone->uz * taz >= 0.0f) &
                        (cone->ux * tbx + cone->uy * tby + cone->uz * tbz >= 0.0f);
      int8 misses =
          (fabs(d) > cone->sin_a) | ((ea < cone->cos_a) & (eb < cone->cos_a) & ~inside_arc);
      covers &= ~(arc & misses);
    }
    for (int k = cs->first_edge[v]; k < cs->first_edge[v + 1] && pn_any(covers); ++k) {
      const EdgePlane8* e = &cs->plane[k];
      int8 use = covers & e->on;
      if (!pn_any(use)) continue;
      float8 f0 = e->mx * ax + e->my * ay + e->mz * az; /* inside the occluder's cone: > 0 */
      float8 f1 = e->mx * bx + e->my * by + e->mz * bz;
      int8 tied = use & in_plane8(f0, f1, la, lb);
      if (pn_any(tied)) { /* and that plane's edge in this edge's plane (edge_in_plane8) */
        const ContourEdge8* o = &cs->edge[k];
        tied &= edge_in_plane8(msx, msy, msz, o->ax, o->ay, o->az, o->bx, o->by, o->bz);
      }
      covers &= ~keeps_tied_edge8(tied, mex, mey, mez, e->mx, e->my, e->mz, owner, v);
      covers &= clip_interval_id8(f0, f1, use & ~tied, k, &t0, &t1, &id0, &id1);
    }
    if (!pn_any(covers)) continue;
    crossing_ends8(msx, msy, msz, self, cs->plane, PN_VEC_ID_CONTOUR, id0, id1, covers, &e0[nc],
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
    const PieceEnd8* start_end = j < 0 ? lo_end : &e1[j];
    const int8 turned0 =
        turn_to_point8(start_end->x, start_end->y, start_end->z, start_end->set, &p0x, &p0y, &p0z);
    PieceEnd8 stop = *hi_end;
    for (int w = 0; w < nc; ++w) {
      int8 at = valid & (end_at == w);
      if (!pn_any(at)) continue;
      stop.x = select(stop.x, e0[w].x, at);
      stop.y = select(stop.y, e0[w].y, at);
      stop.z = select(stop.z, e0[w].z, at);
      stop.set = select(stop.set, e0[w].set, at);
      stop.id = select(stop.id, e0[w].id, at);
    }
    const int8 turned1 = turn_to_point8(stop.x, stop.y, stop.z, stop.set, &p1x, &p1y, &p1z);
    /* In the crossing lanes the turned ends are the edges' crossing in the face's plane. */
    int8 crossed0 = 0, crossed1 = 0;
    if (pn_any(form->crossing_lanes & (turned0 | turned1))) {
      crossed0 = planar_crossings8(form, ring, cs, self, start_end, form->crossing_lanes & turned0,
                                   &p0x, &p0y, &p0z);
      crossed1 = planar_crossings8(form, ring, cs, self, &stop, form->crossing_lanes & turned1,
                                   &p1x, &p1y, &p1z);
    }
    float8 o0x = 0.0f, o0y = 0.0f, o0z = 0.0f, o1x = 0.0f, o1y = 0.0f, o1z = 0.0f;
    if (pn_any(form->small)) {
      centre_offset8(form, p0x, p0y, p0z, &o0x, &o0y, &o0z);
      centre_offset8(form, p1x, p1y, p1z, &o1x, &o1y, &o1z);
      if (offsets) {
        const int8 keep0 = offsets->on & ~turned0, keep1 = offsets->on & ~turned1;
        o0x = select(o0x, edge_point8(offsets->ax, offsets->bx, st), keep0);
        o0y = select(o0y, edge_point8(offsets->ay, offsets->by, st), keep0);
        o0z = select(o0z, edge_point8(offsets->az, offsets->bz, st), keep0);
        o1x = select(o1x, edge_point8(offsets->ax, offsets->bx, end), keep1);
        o1y = select(o1y, edge_point8(offsets->ay, offsets->by, end), keep1);
        o1z = select(o1z, edge_point8(offsets->az, offsets->bz, end), keep1);
      }
    }
    /* An occluder's piece (no offsets) is off the face's plane; so are turned ends, but for the
     * crossings found in it. */
    const int8 off0 = (offsets ? turned0 : (int8)(-1)) & ~crossed0,
               off1 = (offsets ? turned1 : (int8)(-1)) & ~crossed1;
    /* N·p at each end, for the planar form: from the occluder's vertices' heights along its edge,
     * but at turned ends. */
    float8 np0 = 0.0f, np1 = 0.0f;
    if (pn_any(form->planar_lanes)) {
      np0 = plane_dot8(form, p0x, p0y, p0z);
      np1 = plane_dot8(form, p1x, p1y, p1z);
      if (edge && planar_heights_kept(form->plane)) {
        np0 = select(edge_point8(edge->na, edge->nb, st), np0, turned0);
        np1 = select(edge_point8(edge->na, edge->nb, end), np1, turned1);
      }
    }
    float8 term = form_piece_term8(form, p0x, p0y, p0z, p1x, p1y, p1z, o0x, o0y, o0z, o1x, o1y, o1z,
                                   nx, ny, nz, off0, off1, np0, np1, valid);
    pn_sum_add8(acc, select((float8)(0.0f), term, valid));
  }
}
