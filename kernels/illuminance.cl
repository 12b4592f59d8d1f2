/* Exact direct illuminance at sample points from Lambertian convex sources, with occlusion by
 * convex polyhedra (Nishita & Nakamae, §2.5; docs/method.md, docs/architecture.md).
 *
 * Work layout: one work-item computes PN_LANES (8) consecutive points, one per float8 lane,
 * because PoCL does not vectorise atan2 across work-items (explicit lanes are about 5× faster).
 * With culling, lanes whose view of a face may be shaded take the eight-lane penumbra path
 * (penumbra_lanes.cl); the few it hands back, and every shaded lane of the plain path, take the
 * scalar one (penumbra_scalar.cl). */

#include "penumbra_lanes.cl"
#include "penumbra_scalar.cl"

/* The kernel: E (lx) at PN_LANES points per work-item, summed over every source face, and each
 * point's shadow class per source (host/shadow/shadow_class.hpp: bit 0 some light arrives, bit 1
 * an occluder may block), written source by source with row length params.sourceStride.
 * Points are structure-of-arrays, padded by the host to a multiple of PN_LANES, their positions
 * double-float (point_x + point_x_lo, …: PnPosition's hi and lo parts). params.paths
 * selects the path (PN_PATH_*). With params.linked, work-item g takes only the faces
 * link_faces[k], k in [link_start[g], link_start[g + 1]) (a link: a face and the work-item's
 * points), its patch entry is patch_faces[k], and E from each link alone is written at
 * illuminance_lx[k · PN_LANES + lane]; no classes. The host binds these arguments by name and in
 * this order (engine/kernel_scene.cpp; tests/launch_interface_test.cpp holds the two together). */

__kernel void illuminance(
    const PnLaunchParams params, __global const float* point_x, __global const float* point_y,
    __global const float* point_z, __global const float* point_x_lo,
    __global const float* point_y_lo, __global const float* point_z_lo,
    __global const float* normal_x, __global const float* normal_y, __global const float* normal_z,
    __global const int* point_solid, __global const PnSourceFace* faces,
    __global const PnPosition* source_vertices, __global const PnLuminancePolynomial* luminances,
    __global const PnOccluder* occluders, __global const float4* planes, __global const int4* edges,
    __global const PnPosition* occluder_vertices, __global const PnAperture* apertures,
    __global const PnPatchFace* patch_faces, __global const int* candidates,
    __global const int* link_start, __global const int* link_faces, __global float* illuminance_lx,
    __global int* errors, __global uchar* classes) {
  const PnSceneTables tables = {faces, source_vertices,   luminances, occluders,   planes,
                                edges, occluder_vertices, apertures,  patch_faces, candidates};
  const bool culling = (params.paths & PN_PATH_CULLING) != 0;
  const bool lanes_path = culling && (params.paths & PN_PATH_LANES) != 0;
  const size_t g = get_global_id(0);
  float8 px = vload8(g, point_x), py = vload8(g, point_y), pz = vload8(g, point_z);
  /* Each point's own length tolerance: float's resolution where it lies (prelude.cl). */
  const float8 eps_length = length_tolerance8(params.epsLength, px, py, pz);
  float8 lx = vload8(g, point_x_lo), ly = vload8(g, point_y_lo), lz = vload8(g, point_z_lo);
  float8 nx = vload8(g, normal_x), ny = vload8(g, normal_y), nz = vload8(g, normal_z);
  int8 own = vload8(g, point_solid);
  const Points8 points = {px, py, pz, lx, ly, lz, nx, ny, nz, own};
  float lane_px[PN_LANES], lane_py[PN_LANES], lane_pz[PN_LANES];
  float lane_lx[PN_LANES], lane_ly[PN_LANES], lane_lz[PN_LANES];
  float lane_nx[PN_LANES], lane_ny[PN_LANES], lane_nz[PN_LANES];
  int lane_own[PN_LANES];
  float lane_eps[PN_LANES];
  vstore8(eps_length, 0, lane_eps);
  vstore8(px, 0, lane_px);
  vstore8(py, 0, lane_py);
  vstore8(pz, 0, lane_pz);
  vstore8(lx, 0, lane_lx);
  vstore8(ly, 0, lane_ly);
  vstore8(lz, 0, lane_lz);
  vstore8(nx, 0, lane_nx);
  vstore8(ny, 0, lane_ny);
  vstore8(nz, 0, lane_nz);
  vstore8(own, 0, lane_own);

  /* params.bySource: illuminance_lx holds E per source ([source][padded point], like classes); else
   * the sum. */
  PnSum8 e_total = {0.0f, 0.0f}, e_source = {0.0f, 0.0f};
  int8 reaches = 0, blocked = 0; /* per source, reset after its last face */
  int error = 0;
  const int first_link = params.linked ? link_start[g] : 0;
  const int end_link = params.linked ? link_start[g + 1] : params.faceCount;
  for (int k = first_link; k < end_link; ++k) {
    const int f = params.linked ? link_faces[k] : k;
    PnSourceFace face = tables.faces[f];
    PnPatchFace pf = tables.patchFaces[params.linked ? (size_t)k : g * params.faceCount + f];
    if (pf.faceClass == PN_CLASS_UMBRA) /* the host found every lane in one occluder's umbra */
      blocked |= ((int8)(pf.facingLanes) >> (int8)(0, 1, 2, 3, 4, 5, 6, 7)) & 1;
    else if (pf.faceClass != PN_CLASS_C) { /* class C: nothing from this face (Nishita eq. 3) */
      /* Lanes that see the face through its aperture (culling only): its visible rectangle;
       * `dark` lanes see none of it past the wall. */
      ApertureView8 view;
      PnAperture ap;
      view.use = 0;
      view.u0 = view.u1 = view.v0 = view.v1 = view.depth = 0.0f;
      if (culling && face.aperture >= 0) {
        ap = tables.apertures[face.aperture];
        view = aperture_view8(px, py, pz, face, ap, eps_length);
      }
      int8 dark = view.use & ((view.u1 <= view.u0) | (view.v1 <= view.v0));
      float8 e_face = 0.0f;
      if (!all(view.use)) {
        bool cut = false;
        e_face = whole_face8(&points, face, &tables, &cut);
        if (cut) e_face = unoccluded_face8(&points, face, &tables);
      }
      if (pn_any(view.use & ~dark)) {
        const PnEmission em = emission_of(face, &tables); /* uniform, or the sky's polynomial */
        e_face =
            select(e_face, unoccluded_aperture8(view, ap, face.plane, nx, ny, nz, &em), view.use);
      }
      e_face = select(e_face, (float8)(0.0f), dark);
      int8 facing = e_face > 0.0f;
      int8 inside[PN_VEC_MASKS]; /* per candidate, the lanes in its penumbra volume */
      ShadowTests t =
          shadow_tests8(px, py, pz, own, face, pf, culling, view, ap, &tables, eps_length, inside);
      t.shaded &= ~dark;
      t.umbra |= dark;
      facing |= dark;
      e_face = select(e_face, (float8)(0.0f), t.umbra);
      int8 scalar_lanes = t.shaded;
      /* The eight-lane path; the lanes whose occluders it could not hold beside the others' get
       * another call among themselves, whose union of occluders is smaller, while that helps. */
      if (lanes_path) {
        const FaceView8 fv = {face, pf, view, ap};
        int8 pending = t.shaded;
        scalar_lanes = 0;
        for (int pass = 0; pass < PN_VEC_PASSES && pn_any(pending); ++pass) {
          int8 asked = pending, scalar;
          float8 e_pen =
              penumbra_face8(&points, asked, &fv, &tables, eps_length, inside, &pending, &scalar);
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
          float3 p_lo = (float3)(lane_lx[l], lane_ly[l], lane_lz[l]);
          float3 n = (float3)(lane_nx[l], lane_ny[l], lane_nz[l]);
          float3 corners[4];
          if (lane_ap[l])
            for (int i = 0; i < 4; ++i)
              corners[i] = (float3)(lane_cx[i][l], lane_cy[i][l], lane_cz[i][l]);
          lane_e[l] = penumbra_face(p, p_lo, n, lane_own[l], face, pf, culling, &tables,
                                    lane_eps[l], lane_ap[l] != 0, corners, &error);
        }
        e_face = vload8(0, lane_e);
      }
      pn_sum_add8(&e_source, face.halfLuminance * e_face);
      reaches |= facing & ~t.umbra;
      blocked |= facing & (t.shaded | t.umbra);
    }
    if (params.linked) {
      vstore8(e_source.s + e_source.c, k, illuminance_lx);
      e_source.s = e_source.c = 0.0f;
    } else if (f + 1 == params.faceCount || tables.faces[f + 1].source != face.source) {
      int8 cls = (reaches & 1) | ((blocked & 1) << 1);
      vstore8(convert_uchar8(cls), 0,
              classes + (size_t)face.source * params.sourceStride + g * PN_LANES);
      if (params.bySource)
        vstore8(e_source.s + e_source.c, 0,
                illuminance_lx + (size_t)face.source * params.sourceStride + g * PN_LANES);
      pn_sum_add8(&e_total, e_source.s);
      pn_sum_add8(&e_total, e_source.c);
      e_source.s = e_source.c = 0.0f;
      reaches = 0;
      blocked = 0;
    }
  }
  if (!params.bySource && !params.linked) vstore8(e_total.s + e_total.c, g, illuminance_lx);
  errors[g] = error;
}
