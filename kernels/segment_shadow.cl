/* The point model's hard shadow: whether the segment from a point to a luminaire's photometric
 * centre runs through a convex solid. Cyrus–Beck clipping against the solid's planes moved
 * inwards by the length tolerance; a chord no longer than the tolerance does not block, so that
 * touching and grazing (a point on a neighbouring solid's face, a centre flush with a ceiling)
 * never shade. */

#include "prelude.cl"

inline bool pn_segment_blocked(PnShadowSolid s, __global const float4* planes, float3 p, float3 c,
                               float eps) {
  const float3 lo = s.lo.xyz, hi = s.hi.xyz;
  if (any(fmax(p, c) < lo) || any(fmin(p, c) > hi)) return false;
  const float3 w = c - p;
  float enter = 0.0f, leave = 1.0f;
  for (int k = 0; k < s.planeCount; ++k) {
    const float4 pl = planes[s.firstPlane + k];
    const float height = dot(pl.xyz, p) - (pl.w - eps); /* < 0 inside the shrunk solid */
    const float rate = dot(pl.xyz, w);
    if (rate == 0.0f) {
      if (height >= 0.0f) return false;
      continue;
    }
    const float t = -height / rate;
    if (rate > 0.0f)
      leave = fmin(leave, t);
    else
      enter = fmax(enter, t);
    if (enter >= leave) return false;
  }
  return (leave - enter) * length(w) > eps;
}

/* Whether any solid but the point's own blocks the segment p → c. */
inline bool pn_point_shaded(__global const PnShadowSolid* solids, int solid_count,
                            __global const float4* planes, int own, float3 p, float3 c, float eps) {
  for (int i = 0; i < solid_count; ++i) {
    const PnShadowSolid s = solids[i];
    if (s.solid != own && pn_segment_blocked(s, planes, p, c, eps)) return true;
  }
  return false;
}
