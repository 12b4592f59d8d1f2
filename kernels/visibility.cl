#include "shared_types.h"

/* Primary visibility (Nishita §2.2 step ii, done per sample rather than by scanline polygon
 * sorting): for every sample of the image, the nearest face a ray from the eye meets.
 *
 * Positions are relative to the eye: rays start at the origin, and the host passes every plane
 * as n·(x − eye) = w − n·eye, formed in double (render/visibility_engine.cpp), so that float
 * resolves what lies near the eye however far the scene's coordinates are from their origin.
 *
 * Samples form a W × H grid (pixels × supersampling, row-major, row 0 at the top). The ray of
 * sample (X, Y) is forward + sx·right + sy·up with sx, sy in (-1, 1) at the sample's centre;
 * right and up are pre-scaled by the field of view on the host. The host bins objects into
 * screen tiles of PN_VISIBILITY_TILE² samples (the objects whose projection may cover the tile,
 * in scene order), so a sample tests only its tile's list.
 *
 * Output per sample: the face id (0: nothing is hit) and the ray parameter t of the hit (the
 * hit point is eye + t·direction, with the unnormalised direction above).
 *
 * Ties in t: a source wins against a solid's face it lies on (a panel flush with the ceiling
 * would otherwise lose to the ceiling, in whichever order they come, since both give the same t
 * up to float rounding): a source counts up to PN_EPS_REL·t behind the nearest solid, and a solid
 * replaces a source only when it is nearer by more than that. Other ties go to the earlier
 * object in scene order, which is also the tile list's order.
 *
 * Build options from the host: -DPN_EPS_REL=<Tolerance::kKernelRelative>. */

/* Ray against the intersection of half-spaces n·x <= w: the entering parameter and the plane
 * it enters through, or -1 when the ray misses, starts inside, or enters beyond t_best. */
static int hit_solid(float3 o, float3 d, __global const float4* planes, int first, int count,
                     float t_best, float* t_hit) {
  float t_near = 0.0f, t_far = t_best;
  int entered = -1;
  for (int i = 0; i < count; ++i) {
    float4 pl = planes[first + i];
    float denom = dot(pl.xyz, d);
    float dist = pl.w - dot(pl.xyz, o); /* >= 0: the origin is inside this plane */
    if (denom < 0.0f) {
      float t = dist / denom;
      if (t > t_near) {
        t_near = t;
        entered = first + i;
      }
    } else if (denom > 0.0f) {
      t_far = min(t_far, dist / denom);
    } else if (dist < 0.0f) {
      return -1; /* parallel and outside */
    }
  }
  if (entered < 0 || t_near > t_far || t_near >= t_best) return -1;
  *t_hit = t_near;
  return entered - first;
}

/* Ray against a convex polygon seen from its front (emitting) side. */
static int hit_polygon(float3 o, float3 d, __global const float4* planes, int first, int count,
                       float t_best, float* t_hit) {
  float4 pl = planes[first];
  float denom = dot(pl.xyz, d);
  if (denom >= 0.0f) return -1; /* seen from behind or edge-on */
  float t = (pl.w - dot(pl.xyz, o)) / denom;
  if (t <= 0.0f || t >= t_best) return -1;
  float3 x = o + t * d;
  for (int i = 1; i < count; ++i) {
    float4 side = planes[first + i];
    if (dot(side.xyz, x) > side.w) return -1;
  }
  *t_hit = t;
  return 0;
}

__kernel void visibility(const float4 forward, const float4 right, const float4 up, const int width,
                         const int height, const int tiles_across, __global const int* tile_start,
                         __global const int* tile_objects, __global const PnVisibleObject* objects,
                         __global const float4* planes, __global uint* face_ids,
                         __global float* t_out) {
  const int g = (int)get_global_id(0);
  if (g >= width * height) return;
  const int x = g % width, y = g / width;
  const float sx = 2.0f * ((float)x + 0.5f) / (float)width - 1.0f;
  const float sy = 1.0f - 2.0f * ((float)y + 0.5f) / (float)height;
  const float3 o = (float3)(0.0f); /* the eye */
  const float3 d = forward.xyz + sx * right.xyz + sy * up.xyz;

  const int tile = (y / PN_VISIBILITY_TILE) * tiles_across + x / PN_VISIBILITY_TILE;
  float t_best = INFINITY;
  uint best = 0;
  bool best_is_source = false;
  for (int k = tile_start[tile]; k < tile_start[tile + 1]; ++k) {
    PnVisibleObject obj = objects[tile_objects[k]];
    const bool source = obj.kind != PN_VISIBLE_SOLID;
    /* How far away a hit may be and still be the nearest (the tie rule above). */
    const float limit = source == best_is_source ? t_best
                        : source                 ? t_best * (1.0f + PN_EPS_REL)
                                                 : t_best * (1.0f - PN_EPS_REL);
    float t = 0.0f;
    int face = obj.kind == PN_VISIBLE_POLYGON
                   ? hit_polygon(o, d, planes, obj.firstPlane, obj.planeCount, limit, &t)
                   : hit_solid(o, d, planes, obj.firstPlane, obj.planeCount, limit, &t);
    if (face >= 0) {
      t_best = t;
      best = (uint)(obj.firstFaceId + face);
      best_is_source = source;
    }
  }
  face_ids[g] = best;
  t_out[g] = best != 0 ? t_best : 0.0f;
}
