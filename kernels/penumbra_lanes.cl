/* The penumbra path in eight lanes for one face: the source polygon, the active occluders' contour
 * edges, and the integral over the visible region's boundary (lane_edges.cl). */

#include "lane_edges.cl"
#include "occluders.cl"

/* E of the face at the lanes in `asked` (others 0). Left out: in *rest the lanes whose occluders
 * did not fit beside the other lanes' (another call among themselves may hold them), in *scalar
 * those this path cannot take. */
float8 penumbra_face8(float8 px, float8 py, float8 pz, float8 nx, float8 ny, float8 nz, int8 own,
                      int8 asked, PnSourceFace face, PnPatchFace pf, ApertureView8 view,
                      PnAperture ap, const PnSceneTables* tables, float eps_length,
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
    float4 q = tables->sourceVertices[face.firstVertex + i];
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
  int8 lanes = asked & in_front8(face, px, py, pz) & (rise > PN_EPS_REL);
  if (!pn_any(lanes)) return 0.0f;
  /* Side planes of S': the face's edges, and the horizon where it cuts the face. */
  float8 smx[PN_VEC_SOURCE], smy[PN_VEC_SOURCE], smz[PN_VEC_SOURCE];
  HorizonChord8 chord;
  chord_begin8(&chord);
  for (int i = 0; i < m; ++i) {
    int j = i + 1 == m ? 0 : i + 1;
    side_normal8(sx[i], sy[i], sz[i], sx[j], sy[j], sz[j], &smx[i], &smy[i], &smz[i]);
    int8 a_in = sh[i] >= 0.0f, b_in = sh[j] >= 0.0f;
    float8 t = sh[i] / (sh[i] - sh[j]);
    float8 cx = edge_point8(sx[i], sx[j], t), cy = edge_point8(sy[i], sy[j], t),
           cz = edge_point8(sz[i], sz[j], t);
    chord_track8(&chord, a_in, b_in, cx, cy, cz);
  }
  int8 cut = chord_cut8(&chord);
  float8 cmx = 0.0f, cmy = 0.0f, cmz = 0.0f; /* the chord's side normal */
  if (pn_any(cut))
    side_normal8(chord.exit_x, chord.exit_y, chord.exit_z, chord.entry_x, chord.entry_y,
                 chord.entry_z, &cmx, &cmy, &cmz);
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
    PnOccluder o = tables->occluders[occluder_index(i, pf, face, tables)];
    if (i >= PN_VEC_MASKS) {
      act &= own != (int8)(o.solid);
      if (o.behindAperture) act &= ~view.use;
      act = in_penumbra_volume8(o, tables, px, py, pz, eps_length, act);
    }
    act = not_separated8(o, tables, px, py, pz, eps_length, act);
    if (!pn_any(act)) continue;
    /* The bounding sphere against the pyramid P + cone(S'). */
    float8 cx = o.bound.x - px, cy = o.bound.y - py, cz = o.bound.z - pz;
    act &= (nx * cx + ny * cy + nz * cz) >= -o.bound.w;
    for (int j = 0; j < m && pn_any(act); ++j)
      act &= (smx[j] * cx + smy[j] * cy + smz[j] * cz) <= o.bound.w;
    if (i >= PN_VEC_MASKS && pn_any(act & view.use))
      act &= ~(view.use &
               misses_aperture_view8(px, py, pz, view, ap, face.plane, o, tables, eps_length));
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
      front[j] = face_sees8(o, j, tables, px, py, pz, eps_length);
      any_front |= front[j];
    }
    *scalar |= act & ~any_front; /* P lies on this solid: the scalar path clips S' by it */
    act &= any_front;
    if (!pn_any(act)) continue;
    /* Only the edges on some lane's contour are kept (a box has 12 edges, 4 to 6 on a contour). */
    int c = cs.first[cs.na];
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
      float4 f = tables->occluderVertices[o.firstVertex + ed.x],
             g = tables->occluderVertices[o.firstVertex + ed.y];
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
    cs.occ[cs.na] = occluder_index(i, pf, face, tables);
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
    PnOccluder ou = tables->occluders[cs.occ[u]];
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
          float4 x = tables->occluderVertices[ou.firstVertex + q];
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
  visible_edge_term8(chord.exit_x, chord.exit_y, chord.exit_z, chord.entry_x, chord.entry_y,
                     chord.entry_z, cmx, cmy, cmz, m, (float8)(0.0f), (float8)(1.0f), &none, &none,
                     lanes & cut, -1, nx, ny, nz, &cs, &sum);
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
        int8 tied = use & in_plane8(f0, f1, la, lb);
        on &= ~tied;
        on &= clip_interval_id8(f0, f1, use & ~tied, i, &t0, &t1, &id0, &id1);
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
