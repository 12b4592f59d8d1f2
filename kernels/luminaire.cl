/* The point model of photometric luminaires (docs/method.md, "Photometric luminaires"): at each
 * point, from each placed luminaire's photometric centre c,
 *   E = I(ω) · cos θ / d²,
 * ω the direction c → point in the luminaire's frame, θ between the point's normal and the
 * direction to c, d = |c − p|; a cell of a subdivided opening is such a source at the cell's
 * centre, times its share of the table. A point behind its own surface (cos θ <= 0) and a point
 * whose segment to c runs through a solid receive nothing from that luminaire; `seen` says which
 * luminaires a point sees ([luminaire][point], row length params.pointStride), for a render's
 * interval plan. One work-item per
 * point; the luminaires' sum is compensated (prelude.cl). The host binds the arguments in this
 * order (engine/luminaire_engine.cpp). */

#include "photometric_table.cl"
#include "prelude.cl"
#include "segment_shadow.cl"

__kernel void luminaire_illuminance(const PnLuminaireParams params, __global const float* point_x,
                                    __global const float* point_y, __global const float* point_z,
                                    __global const float* normal_x, __global const float* normal_y,
                                    __global const float* normal_z, __global const int* point_solid,
                                    __global const PnLuminaire* luminaires,
                                    __global const PnCandelaTable* tables,
                                    __global const float* angles, __global const float* candela,
                                    __global const PnShadowSolid* solids,
                                    __global const float4* solid_planes,
                                    __global float* illuminance_lx, __global uchar* seen) {
  const int i = get_global_id(0);
  if (i >= params.pointCount) return;
  const float3 p = (float3)(point_x[i], point_y[i], point_z[i]);
  const float3 n = (float3)(normal_x[i], normal_y[i], normal_z[i]);
  const int own = point_solid[i];
  PnSum e = {0.0f, 0.0f};
  for (int l = 0; l < params.luminaireCount; ++l) {
    const PnLuminaire lum = luminaires[l];
    const float3 w = lum.centre.xyz - p; /* towards the centre */
    const float d2 = dot(w, w);
    if (d2 <= 0.0f) {
      seen[l * params.pointStride + i] = 0;
      continue;
    }
    const float cos_theta = dot(n, w) / sqrt(d2);
    /* The segment's points are no farther from the origin than its ends: their tolerance. */
    const float3 c = lum.centre.xyz;
    const float eps = fmax(length_tolerance1(params.epsLength, p.x, p.y, p.z),
                           length_tolerance1(params.epsLength, c.x, c.y, c.z));
    const bool lit = cos_theta > 0.0f &&
                     !pn_point_shaded(solids, params.solidCount, solid_planes, own, p, c, eps);
    seen[l * params.pointStride + i] = lit ? 1 : 0;
    if (!lit) continue;
    const float3 away = -w; /* from the centre towards the point */
    const float3 in_frame = (float3)(dot(lum.toLocal0.xyz, away), dot(lum.toLocal1.xyz, away),
                                     dot(lum.toLocal2.xyz, away));
    const float intensity = pn_table_intensity(tables[lum.table], angles, candela, in_frame);
    pn_sum_add(&e, lum.share * intensity * cos_theta / d2);
  }
  illuminance_lx[i] = e.s + e.c;
}
