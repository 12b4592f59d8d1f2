/* The penumbra path in eight lanes for one face: the source polygon S', the active occluders'
 * contour edges, and the integral over the visible region's boundary (lane_edges.cl). */

#include "lane_edges.cl"
#include "occluders.cl"

/* A source face as the lanes see it: the face, the patch's entry for it and, for the lanes in
 * view.use, the rectangle of it they see through its aperture. */
typedef struct {
  PnSourceFace face;
  PnPatchFace pf;
  ApertureView8 view;
  PnAperture ap;
} FaceView8;

/* S' per lane, relative to P: the face's vertices (or the lane's aperture rectangle) with their
 * heights above the horizon, and its side planes by id (crossing_ends8 reads them so): the face's
 * edges 0 … m − 1, then the horizon chord m in the lanes it cuts. */
typedef struct {
  float8 x[PN_VEC_SOURCE], y[PN_VEC_SOURCE], z[PN_VEC_SOURCE], h[PN_VEC_SOURCE];
  EdgePlane8 side[PN_VEC_SOURCE + 1];
  HorizonChord8 chord;
  /* Where the face is small (form.small): its vertices' and the chord's ends' offsets from
   * form.centre (contour.cl, PnPieceForm), exact in the lanes of `exact` (those that see the face
   * itself, not an aperture's rectangle). */
  float8 ox[PN_VEC_SOURCE], oy[PN_VEC_SOURCE], oz[PN_VEC_SOURCE];
  HorizonChord8 chord_offset;
  int8 exact;
  int8 cut;              /* lanes whose horizon cuts the face */
  int m;                 /* the face's vertex count */
  PnEmission emission;   /* how the face emits (luminance_moments.cl) */
  PnPieceForm8 form;     /* how its pieces are integrated (contour.cl), reading `emission` */
  PnPlanarFrame8 planar; /* the face's planar frame, where form.crossing_lanes has a lane */
} SourcePolygon8;

/* Fills S' for the lanes in `asked` and returns those that see the face: in front of it and not
 * edge-on (source_polygon says why). The side planes are left unset when there are none. */
int8 source_polygon8(SourcePolygon8* s, const Points8* pts, int8 asked, const FaceView8* fv,
                     const PnSceneTables* tables) {
  const float8 px = pts->px, py = pts->py, pz = pts->pz, nx = pts->nx, ny = pts->ny, nz = pts->nz;
  const PnSourceFace face = fv->face;
  const int m = face.vertexCount;
  s->m = m;
  s->emission = emission_of(face, tables);
  s->form.em = &s->emission;
  float8 x0, y0, z0;
  int k = 0;
  pn_from8(tables->sourceVertices[face.firstVertex], pts, &x0, &y0, &z0);
  const bool small =
      small_face8(pts, face, tables, x0, y0, z0, &s->form.centre, &k, &s->form.small);
  s->exact = ~fv->view.use;
  s->form.plane = face.plane;
  s->form.height = 0.0f;
  if (small)
    s->form.height = face.plane.x * s->form.centre.x + face.plane.y * s->form.centre.y +
                     face.plane.z * s->form.centre.z;
  /* The planar form where the lanes see the face near its plane (planar_term.cl), as
   * unoccluded_face8 takes it. */
  s->form.planar = &s->planar;
  s->form.planar_lanes = planar_lanes8(face, &s->emission, x0, y0, z0, false) & ~s->form.small;
  s->form.crossing_lanes = planar_lanes8(face, &s->emission, x0, y0, z0, true) & ~s->form.small;
  if (pn_any(s->form.crossing_lanes)) s->planar = planar_frame8(pts, face, tables);
  for (int i = 0; i < m; ++i) {
    pn_from8(tables->sourceVertices[face.firstVertex + i], pts, &s->x[i], &s->y[i], &s->z[i]);
    if (pn_any(fv->view.use)) {
      float8 cx, cy, cz;
      aperture_corner8(fv->view, fv->ap, face.plane, i, &cx, &cy, &cz);
      s->x[i] = select(s->x[i], cx, fv->view.use);
      s->y[i] = select(s->y[i], cy, fv->view.use);
      s->z[i] = select(s->z[i], cz, fv->view.use);
    }
    s->h[i] = nx * s->x[i] + ny * s->y[i] + nz * s->z[i];
    if (small) {
      const float3 o = vertex_offset(face, i, k, tables);
      s->ox[i] = o.x;
      s->oy[i] = o.y;
      s->oz[i] = o.z;
    }
  }
  float8 rise = 0.0f;
  for (int i = 0; i < m; ++i)
    rise = fmax(rise, s->h[i] / sqrt(s->x[i] * s->x[i] + s->y[i] * s->y[i] + s->z[i] * s->z[i]));
  const int8 lanes = asked & in_front8(face, px, py, pz) & (rise > PN_EPS_REL);
  if (!pn_any(lanes)) return lanes;
  chord_begin8(&s->chord);
  chord_begin8(&s->chord_offset);
  for (int i = 0; i < m; ++i) {
    int j = i + 1 == m ? 0 : i + 1;
    EdgePlane8* side = &s->side[i];
    side_normal8(s->x[i], s->y[i], s->z[i], s->x[j], s->y[j], s->z[j], &side->mx, &side->my,
                 &side->mz);
    int8 a_in = s->h[i] >= 0.0f, b_in = s->h[j] >= 0.0f;
    float8 t = s->h[i] / (s->h[i] - s->h[j]);
    float8 cx = edge_point8(s->x[i], s->x[j], t), cy = edge_point8(s->y[i], s->y[j], t),
           cz = edge_point8(s->z[i], s->z[j], t);
    chord_track8(&s->chord, a_in, b_in, cx, cy, cz);
    if (small)
      chord_track8(&s->chord_offset, a_in, b_in, edge_point8(s->ox[i], s->ox[j], t),
                   edge_point8(s->oy[i], s->oy[j], t), edge_point8(s->oz[i], s->oz[j], t));
  }
  s->cut = chord_cut8(&s->chord);
  EdgePlane8* chord_side = &s->side[m];
  chord_side->mx = chord_side->my = chord_side->mz = 0.0f;
  if (pn_any(s->cut))
    side_normal8(s->chord.exit_x, s->chord.exit_y, s->chord.exit_z, s->chord.entry_x,
                 s->chord.entry_y, s->chord.entry_z, &chord_side->mx, &chord_side->my,
                 &chord_side->mz);
  return lanes;
}

/* The bounding cone of a sphere of radius r whose centre is (cx, cy, cz) from P. */
inline void bound_cone8(BoundCone8* cone, float8 cx, float8 cy, float8 cz, float r) {
  float8 dist = sqrt(cx * cx + cy * cy + cz * cz);
  float8 sin_a = r / dist;
  int8 outside = dist > r;
  cone->ux = cx / dist;
  cone->uy = cy / dist;
  cone->uz = cz / dist;
  cone->sin_a = select((float8)(2.0f), sin_a + PN_VEC_CONE_MARGIN, outside);
  cone->cos_a =
      select((float8)(-2.0f), sqrt(fmax(1.0f - sin_a * sin_a, 0.0f)) - PN_VEC_CONE_MARGIN, outside);
}

/* The occluders active in some of `lanes`, in candidate order, with the edges on some lane's
 * contour (a box has 12 edges, 4 to 6 on a contour), hole-oriented. Lanes left out go to *rest
 * (what did not fit) or *scalar (what this path does not take). */
void gather_occluders8(Contours8* cs, const SourcePolygon8* s, const Points8* pts, int8 lanes,
                       const FaceView8* fv, const PnSceneTables* tables, float8 eps_length,
                       const int8* inside, int8* rest, int8* scalar) {
  const float8 px = pts->px, py = pts->py, pz = pts->pz, nx = pts->nx, ny = pts->ny, nz = pts->nz;
  const PnSourceFace face = fv->face;
  const ApertureView8 view = fv->view;
  cs->count = 0;
  cs->first_edge[0] = 0;
  const int count = occluder_count(fv->pf, face);
  for (int i = 0; i < count; ++i) {
    int8 act = lanes & ~(*rest | *scalar); /* left: not this call's */
    /* The first PN_VEC_MASKS candidates come with shadow_tests8's lanes (its own solid, behind
     * the aperture, the penumbra volume, the aperture's pyramid): only what it does not test. */
    if (i < PN_VEC_MASKS) act &= inside[i];
    if (!pn_any(act)) continue;
    const int index = occluder_index(i, fv->pf, face, tables);
    PnOccluder o = tables->occluders[index];
    if (i >= PN_VEC_MASKS) {
      act &= pts->own != (int8)(o.solid);
      if (o.behindAperture) act &= ~view.use;
      act = in_penumbra_volume8(o, tables, px, py, pz, eps_length, act);
    }
    act = not_separated8(o, tables, px, py, pz, eps_length, act);
    if (!pn_any(act)) continue;
    /* The bounding sphere against the pyramid P + cone(S'). */
    float8 cx = o.bound.x - px, cy = o.bound.y - py, cz = o.bound.z - pz;
    act &= (nx * cx + ny * cy + nz * cz) >= -o.bound.w;
    for (int j = 0; j < s->m && pn_any(act); ++j)
      act &= (s->side[j].mx * cx + s->side[j].my * cy + s->side[j].mz * cz) <= o.bound.w;
    if (i >= PN_VEC_MASKS && pn_any(act & view.use))
      act &= ~(view.use &
               misses_aperture_view8(px, py, pz, view, fv->ap, face.plane, o, tables, eps_length));
    if (!pn_any(act)) continue;
    if (o.planeCount > PN_VEC_FACES) {
      *scalar |= act;
      continue;
    }
    if (cs->count == PN_VEC_OCCLUDERS) {
      *rest |= act;
      continue;
    }
    int8 front[PN_VEC_FACES];
    int8 any_front = 0;
    for (int j = 0; j < o.planeCount; ++j) {
      front[j] = face_sees8(o, j, tables, px, py, pz, eps_length);
      any_front |= front[j];
    }
    *scalar |= act & ~any_front; /* P lies on this solid: the scalar path clips S' by it */
    act &= any_front;
    if (!pn_any(act)) continue;
    int c = cs->first_edge[cs->count];
    bool full = false;
    for (int k = 0; k < o.edgeCount; ++k) {
      int4 ed = tables->edges[o.firstEdge + k];
      int8 lf = front[ed.z], rf = front[ed.w];
      int8 on = act & (lf ^ rf);
      if (!pn_any(on)) continue;
      if (c == PN_VEC_EDGES) {
        full = true;
        break;
      }
      float8 fx, fy, fz, gx, gy, gz;
      const PnPosition qf = tables->occluderVertices[o.firstVertex + ed.x];
      const PnPosition qg = tables->occluderVertices[o.firstVertex + ed.y];
      pn_from8(qf, pts, &fx, &fy, &fz);
      pn_from8(qg, pts, &gx, &gy, &gz);
      EdgePlane8* ep = &cs->plane[c];
      ContourEdge8* e = &cs->edge[c++];
      /* run as the face that does not see P does (contour_edge) */
      e->ax = select(fx, gx, lf);
      e->ay = select(fy, gy, lf);
      e->az = select(fz, gz, lf);
      e->bx = select(gx, fx, lf);
      e->by = select(gy, fy, lf);
      e->bz = select(gz, fz, lf);
      e->na = e->nb = 0.0f;
      if (pn_any(s->form.crossing_lanes) && planar_heights_kept(face.plane)) {
        const float8 nf = planar_depth8(qf, fx, fy, fz, fv->face, &s->planar, tables);
        const float8 ng = planar_depth8(qg, gx, gy, gz, fv->face, &s->planar, tables);
        e->na = select(nf, ng, lf);
        e->nb = select(ng, nf, lf);
      }
      side_normal8(e->ax, e->ay, e->az, e->bx, e->by, e->bz, &ep->mx, &ep->my, &ep->mz);
      e->on = on;
      ep->on = on & ((ep->mx != 0.0f) | (ep->my != 0.0f) | (ep->mz != 0.0f));
    }
    if (full) { /* this occluder's edges do not fit: dropped, its lanes left for another call */
      *rest |= act;
      continue;
    }
    int8 whole = act;
    for (int k = cs->first_edge[cs->count]; k < c; ++k)
      whole &= ~(cs->edge[k].on & ~cs->plane[k].on);
    cs->whole[cs->count] = whole;
    cs->occluder[cs->count] = index;
    bound_cone8(&cs->cone[cs->count], cx, cy, cz, o.bound.w);
    cs->lanes[cs->count] = act;
    ++cs->count;
    cs->first_edge[cs->count] = c;
  }
}

/* Drops occluders hidden behind another: where every vertex of u lies inside v's cone (inside
 * each side plane of v's contour by more than eps_length), u's cone lies strictly inside v's, so
 * u adds nothing to the union: it covers no edge v does not cover more, and its own edges are
 * covered. Its lanes are dropped; the pieces, and so the sums, are the same without it. */
void drop_hidden8(Contours8* cs, const Points8* pts, const PnSceneTables* tables,
                  float8 eps_length) {
  const float8 px = pts->px, py = pts->py, pz = pts->pz;
  for (int u = 0; u < cs->count && cs->count > 1; ++u) {
    PnOccluder ou = tables->occluders[cs->occluder[u]];
    int8 hidden_all = 0;
    for (int v = 0; v < cs->count && pn_any(cs->lanes[u] & ~hidden_all); ++v) {
      if (v == u) continue;
      int8 hidden = cs->lanes[u] & cs->lanes[v] & cs->whole[v] & ~hidden_all;
      /* If every vertex of u is inside v's cone, so is u's centroid, the axis of u's bounding
       * cone: outside v's bounding cone (grown by its margin), u is not hidden by v. Most pairs
       * end here, before the test of u's vertices against v's planes. */
      const BoundCone8* cone_u = &cs->cone[u];
      const BoundCone8* cone_v = &cs->cone[v];
      hidden &= cone_u->ux * cone_v->ux + cone_u->uy * cone_v->uy + cone_u->uz * cone_v->uz >=
                cone_v->cos_a;
      for (int k = cs->first_edge[v]; k < cs->first_edge[v + 1] && pn_any(hidden); ++k) {
        const EdgePlane8* e = &cs->plane[k];
        if (!pn_any(hidden & e->on)) continue;
        for (int q = 0; q < ou.vertexCount && pn_any(hidden); ++q) {
          float4 x = tables->occluderVertices[ou.firstVertex + q].hi;
          hidden &=
              ~e->on | (e->mx * (x.x - px) + e->my * (x.y - py) + e->mz * (x.z - pz) > eps_length);
        }
      }
      hidden_all |= hidden;
    }
    if (!pn_any(hidden_all)) continue;
    cs->lanes[u] &= ~hidden_all; /* (a dropped u hides nothing itself) */
    cs->whole[u] &= ~hidden_all;
    for (int k = cs->first_edge[u]; k < cs->first_edge[u + 1]; ++k) {
      cs->plane[k].on &= ~hidden_all;
      cs->edge[k].on &= ~hidden_all;
    }
  }
}

/* The ends of S' edge i: the horizon chord's (exit, entry) when i == m. */
void source_edge8(const SourcePolygon8* s, int i, float8* cx, float8* cy, float8* cz, float8* dx,
                  float8* dy, float8* dz) {
  if (i == s->m) {
    *cx = s->chord.exit_x, *cy = s->chord.exit_y, *cz = s->chord.exit_z;
    *dx = s->chord.entry_x, *dy = s->chord.entry_y, *dz = s->chord.entry_z;
  } else {
    const int j = i + 1 == s->m ? 0 : i + 1;
    *cx = s->x[i], *cy = s->y[i], *cz = s->z[i], *dx = s->x[j], *dy = s->y[j], *dz = s->z[j];
  }
}

/* The lanes of `use` where a contour edge (side plane ep, lengths la and lb, ends at -f0 and -f1
 * along S' side plane i's normal) is tied to S' edge i: it lies in that edge's side plane, and
 * that edge in its own (the tie rule, contour.cl). */
int8 tied_to_side8(const SourcePolygon8* s, int i, const EdgePlane8* ep, int8 use, float8 f0,
                   float8 f1, float8 la, float8 lb) {
  int8 tied = use & in_plane8(f0, f1, la, lb);
  if (!pn_any(tied)) return tied;
  float8 cx, cy, cz, dx, dy, dz;
  source_edge8(s, i, &cx, &cy, &cz, &dx, &dy, &dz);
  return tied & edge_in_plane8(ep->mx, ep->my, ep->mz, cx, cy, cz, dx, dy, dz);
}

/* The lanes where contour edge e (side plane ep) is tied to side plane i of S' (tied_to_side8,
 * as integrate_holes8 reads it), and, in *ux, *uy, *uz, u for that S' edge (snap_end8). */
int8 tied_to_source8(const SourcePolygon8* s, int i, const ContourEdge8* e, const EdgePlane8* ep,
                     float8 la, float8 lb, float8* ux, float8* uy, float8* uz) {
  const EdgePlane8* side = &s->side[i];
  int8 use = e->on & ep->on & ((side->mx != 0.0f) | (side->my != 0.0f) | (side->mz != 0.0f));
  if (i == s->m) use &= s->cut;
  if (!pn_any(use)) return use;
  const float8 f0 = -(side->mx * e->ax + side->my * e->ay + side->mz * e->az);
  const float8 f1 = -(side->mx * e->bx + side->my * e->by + side->mz * e->bz);
  const int8 tied = tied_to_side8(s, i, ep, use, f0, f1, la, lb);
  if (!pn_any(tied)) return tied;
  float8 cx, cy, cz, dx, dy, dz;
  source_edge8(s, i, &cx, &cy, &cz, &dx, &dy, &dz);
  edge_across8(s->form.plane.xyz, cx, cy, cz, dx, dy, dz, ux, uy, uz);
  return tied;
}

/* Moves the vertices of the contour edges tied to an S' edge into that edge's side plane, at
 * every contour edge that ends there, per lane (snap_end8, contour.cl; penumbra_scalar.cl's
 * snap_tied_vertices), and takes their side planes anew. */
#define PN_VEC_TIED_ENDS 8
void snap_tied_vertices8(Contours8* cs, const SourcePolygon8* s) {
  float8 vx[PN_VEC_TIED_ENDS], vy[PN_VEC_TIED_ENDS], vz[PN_VEC_TIED_ENDS];
  float8 ux[PN_VEC_TIED_ENDS], uy[PN_VEC_TIED_ENDS], uz[PN_VEC_TIED_ENDS];
  int8 lanes[PN_VEC_TIED_ENDS];
  int plane[PN_VEC_TIED_ENDS];
  int count = 0;
  const int edges = cs->first_edge[cs->count];
  const int m = s->m;
  int8 plane_use[PN_VEC_SOURCE + 1];
  for (int i = 0; i <= m; ++i) {
    const EdgePlane8* side = &s->side[i];
    plane_use[i] = (side->mx != 0.0f) | (side->my != 0.0f) | (side->mz != 0.0f);
    if (i == m) plane_use[i] &= s->cut;
  }
  /* Most edges have no end near an S' side plane: a test of squares, a little wider than
   * in_plane8's, before the tie rule's own. */
  const float near2 = (1.01f * PN_TIE_REL) * (1.01f * PN_TIE_REL);
  for (int k = 0; k < edges; ++k) {
    const ContourEdge8* e = &cs->edge[k];
    const EdgePlane8* ep = &cs->plane[k];
    const int8 on = e->on & ep->on;
    if (!pn_any(on)) continue;
    const float8 la2 = e->ax * e->ax + e->ay * e->ay + e->az * e->az;
    const float8 lb2 = e->bx * e->bx + e->by * e->by + e->bz * e->bz;
    for (int i = 0; i <= m && count + 2 <= PN_VEC_TIED_ENDS; ++i) {
      const EdgePlane8* side = &s->side[i];
      const float8 f0 = side->mx * e->ax + side->my * e->ay + side->mz * e->az;
      int8 near = on & plane_use[i] & (f0 * f0 <= near2 * la2);
      if (!pn_any(near)) continue;
      const float8 f1 = side->mx * e->bx + side->my * e->by + side->mz * e->bz;
      if (!pn_any(near & (f1 * f1 <= near2 * lb2))) continue;
      float8 x, y, z;
      const int8 tied = tied_to_source8(s, i, e, ep, sqrt(la2), sqrt(lb2), &x, &y, &z);
      if (!pn_any(tied)) continue;
      for (int end = 0; end < 2; ++end, ++count) {
        vx[count] = end ? e->bx : e->ax;
        vy[count] = end ? e->by : e->ay;
        vz[count] = end ? e->bz : e->az;
        ux[count] = x;
        uy[count] = y;
        uz[count] = z;
        lanes[count] = tied;
        plane[count] = i;
      }
    }
  }
  for (int k = 0; k < edges && count > 0; ++k) {
    ContourEdge8* e = &cs->edge[k];
    const float8 ax = e->ax, ay = e->ay, az = e->az, bx = e->bx, by = e->by, bz = e->bz;
    int8 moved = 0;
    for (int r = 0; r < count; ++r) {
      const int8 at_a = e->on & lanes[r] & (ax == vx[r]) & (ay == vy[r]) & (az == vz[r]);
      const int8 at_b = e->on & lanes[r] & (bx == vx[r]) & (by == vy[r]) & (bz == vz[r]);
      if (!pn_any(at_a | at_b)) continue;
      const EdgePlane8* side = &s->side[plane[r]];
      snap_end8(side->mx, side->my, side->mz, ux[r], uy[r], uz[r], at_a, &e->ax, &e->ay, &e->az);
      snap_end8(side->mx, side->my, side->mz, ux[r], uy[r], uz[r], at_b, &e->bx, &e->by, &e->bz);
      moved |= at_a | at_b;
    }
    if (!pn_any(moved)) continue;
    /* the ends' heights move with them (the move is across an S' edge, along the plane but where
     * snap_end takes it along the side plane's normal) */
    e->na += plane_dot8(&s->form, e->ax - ax, e->ay - ay, e->az - az);
    e->nb += plane_dot8(&s->form, e->bx - bx, e->by - by, e->bz - bz);
    EdgePlane8* ep = &cs->plane[k];
    float8 mx, my, mz;
    side_normal8(e->ax, e->ay, e->az, e->bx, e->by, e->bz, &mx, &my, &mz);
    ep->mx = select(ep->mx, mx, moved);
    ep->my = select(ep->my, my, moved);
    ep->mz = select(ep->mz, mz, moved);
  }
}

/* S''s edges as planar_crossings8 reads them. */
inline SourceRing8 source_ring8(const SourcePolygon8* s) {
  const SourceRing8 ring = {s->x, s->y, s->z, &s->chord, s->m};
  return ring;
}

/* What the face's boundary edges are integrated against (visible_edge_term8). */
inline ContourContext8 contour_context8(const SourcePolygon8* s, const Points8* pts,
                                        const Contours8* cs, const SourceRing8* ring) {
  const ContourContext8 ctx = {&s->form, cs, ring, pts->nx, pts->ny, pts->nz};
  return ctx;
}

/* Boundary part (a): the source's edges above the horizon, and the chord. Their ends are vertices
 * or on the horizon, where the edge and the chord compute the same point. */
void integrate_source8(const SourcePolygon8* s, const Points8* pts, int8 lanes, const Contours8* cs,
                       PnSum8* sum) {
  const int m = s->m;
  const SourceRing8 ring = source_ring8(s);
  const ContourContext8 ctx = contour_context8(s, pts, cs, &ring);
  PieceEnd8 none;
  piece_end_clear8(&none);
  for (int i = 0; i < m; ++i) {
    int j = i + 1 == m ? 0 : i + 1;
    int8 a_in = s->h[i] >= 0.0f, b_in = s->h[j] >= 0.0f;
    float8 t = s->h[i] / (s->h[i] - s->h[j]);
    float8 lo = select((float8)(0.0f), t, ~a_in), hi = select((float8)(1.0f), t, ~b_in);
    const ContourEdge8 offsets = {s->ox[i], s->oy[i], s->oz[i], s->ox[j],
                                  s->oy[j], s->oz[j], s->exact};
    const BoundaryEdge8 edge = {s->x[i],     s->y[i], s->z[i], s->x[j],  s->y[j], s->z[j],
                                &s->side[i], i,       -1,      &offsets, 0};
    const EdgeSpan8 span = {lo, hi, &none, &none, lanes & (a_in | b_in)};
    visible_edge_term8(&edge, &span, &ctx, sum);
  }
  const HorizonChord8* chord = &s->chord;
  const HorizonChord8* oc = &s->chord_offset;
  const ContourEdge8 offsets = {oc->exit_x,  oc->exit_y,  oc->exit_z, oc->entry_x,
                                oc->entry_y, oc->entry_z, s->exact};
  const BoundaryEdge8 edge = {chord->exit_x,
                              chord->exit_y,
                              chord->exit_z,
                              chord->entry_x,
                              chord->entry_y,
                              chord->entry_z,
                              &s->side[m],
                              m,
                              -1,
                              &offsets,
                              0};
  const EdgeSpan8 span = {0.0f, 1.0f, &none, &none, lanes & s->cut};
  visible_edge_term8(&edge, &span, &ctx, sum);
}

/* Boundary part (b): the occluders' contour edges inside S', as holes. */
void integrate_holes8(const SourcePolygon8* s, const Points8* pts, int8 lanes, const Contours8* cs,
                      PnSum8* sum, int8* tied_lanes) {
  const int m = s->m;
  const SourceRing8 ring = source_ring8(s);
  const ContourContext8 ctx = contour_context8(s, pts, cs, &ring);
  for (int u = 0; u < cs->count; ++u)
    for (int k = cs->first_edge[u]; k < cs->first_edge[u + 1]; ++k) {
      const ContourEdge8* e = &cs->edge[k];
      int8 on = lanes & e->on;
      if (!pn_any(on)) continue;
      float8 la = sqrt(e->ax * e->ax + e->ay * e->ay + e->az * e->az);
      float8 lb = sqrt(e->bx * e->bx + e->by * e->by + e->bz * e->bz);
      const EdgePlane8* ep = &cs->plane[k];
      float8 t0 = 0.0f, t1 = 1.0f;
      int8 id0 = -1, id1 = -1;
      for (int i = 0; i <= m && pn_any(on); ++i) {
        float8 mx = s->side[i].mx, my = s->side[i].my, mz = s->side[i].mz;
        int8 use = on & ((mx != 0.0f) | (my != 0.0f) | (mz != 0.0f));
        if (i == m) use &= s->cut;
        if (!pn_any(use)) continue;
        float8 f0 = -(mx * e->ax + my * e->ay + mz * e->az);
        float8 f1 = -(mx * e->bx + my * e->by + mz * e->bz);
        /* In a side plane of S' whose edge lies in this edge's plane (tied_to_side8): the
         * source keeps it, or the visible region is empty there. */
        const int8 tied = tied_to_side8(s, i, ep, use, f0, f1, la, lb);
        on &= ~tied;
        *tied_lanes |= tied;
        on &= clip_interval_id8(f0, f1, use & ~tied, i, &t0, &t1, &id0, &id1);
      }
      if (!pn_any(on)) continue;
      PieceEnd8 lo_end, hi_end;
      crossing_ends8(ep->mx, ep->my, ep->mz, PN_VEC_ID_CONTOUR + k, s->side, 0, id0, id1, on,
                     &lo_end, &hi_end);
      const BoundaryEdge8 edge = {
          e->ax, e->ay, e->az, e->bx, e->by, e->bz, ep, PN_VEC_ID_CONTOUR + k, u, 0, e};
      const EdgeSpan8 span = {t0, t1, &lo_end, &hi_end, on};
      visible_edge_term8(&edge, &span, &ctx, sum);
    }
}

/* The sum over the visible contour at the lanes in `lanes` (parts (a) and (b)), with the planar
 * form's closing where it serves; *tied_lanes gets the lanes where an occluder's edge is tied to
 * an S' edge. */
float8 contour_sum8(SourcePolygon8* s, const Points8* pts, int8 lanes, const Contours8* cs,
                    int8* tied_lanes) {
  PnSum8 sum = {0.0f, 0.0f};
  s->planar.dpsi_sum = 0.0f;
  integrate_source8(s, pts, lanes, cs, &sum);
  integrate_holes8(s, pts, lanes, cs, &sum, tied_lanes);
  if (!pn_any(s->form.planar_lanes & lanes)) return sum.s + sum.c;
  return select(sum.s + sum.c, (sum.s + sum.c) + planar_closing8(&s->planar, &s->emission),
                s->form.planar_lanes);
}

/* E of the face at the lanes in `asked` (others 0). Left out: in *rest the lanes whose occluders
 * did not fit beside the other lanes' (another call among themselves may hold them), in *scalar
 * those this path cannot take. */
float8 penumbra_face8(const Points8* pts, int8 asked, const FaceView8* fv,
                      const PnSceneTables* tables, float8 eps_length, const int8* inside,
                      int8* rest, int8* scalar) {
  *rest = 0;
  *scalar = 0;
  if (fv->face.vertexCount > PN_VEC_SOURCE) {
    *scalar = asked;
    return 0.0f;
  }
  SourcePolygon8 s;
  int8 lanes = source_polygon8(&s, pts, asked, fv, tables);
  if (!pn_any(lanes)) return 0.0f;
  Contours8 cs;
  gather_occluders8(&cs, &s, pts, lanes, fv, tables, eps_length, inside, rest, scalar);
  lanes &= ~(*rest | *scalar);
  drop_hidden8(&cs, pts, tables, eps_length);
  int8 tied = 0;
  float8 e = contour_sum8(&s, pts, lanes, &cs, &tied);
  if (pn_any(tied)) {
    /* An occluder's edge tied to an S' edge (rare): its vertices into that edge's side plane,
     * and the lanes that have one integrated again. */
    snap_tied_vertices8(&cs, &s);
    int8 still = 0;
    e = select(e, contour_sum8(&s, pts, tied, &cs, &still), tied);
  }
  return select((float8)(0.0f), fmax(e, 0.0f), lanes);
}
