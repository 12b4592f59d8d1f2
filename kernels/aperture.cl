/* Apertures (host/shadow/aperture.hpp). For the lanes that use the aperture: the visible part of
 * the face, face ∩ cone(P, A), as a rectangle relative to P. A projects from P onto the face's
 * plane by the homothety of ratio k = hS / hA about P (hS, hA: P's heights above the face's
 * and A's planes), so the rectangle is the min/max of two rectangles. Empty (u1 <= u0 or
 * v1 <= v0): the wall hides the whole face. */

#include "lambert.cl"

typedef struct {
  int8 use;              /* lanes strictly in front of A and inside the room's box */
  float8 u0, u1, v0, v1; /* the visible rectangle, coordinates relative to P's */
  float8 depth;          /* the face's plane relative to P along the emission direction */
} ApertureView8;

inline ApertureView8 aperture_view8(float8 px, float8 py, float8 pz, PnSourceFace face,
                                    PnAperture ap, float8 eps_length) {
  ApertureView8 v;
  float8 ha = plane_height8(ap.plane, px, py, pz);
  float8 hs = plane_height8(face.plane, px, py, pz);
  v.use = (ha > eps_length) & (px >= ap.roomLo.x) & (px <= ap.roomHi.x) & (py >= ap.roomLo.y) &
          (py <= ap.roomHi.y) & (pz >= ap.roomLo.z) & (pz <= ap.roomHi.z);
  float8 pu = ap.axisU.x * px + ap.axisU.y * py + ap.axisU.z * pz;
  float8 pv = ap.axisV.x * px + ap.axisV.y * py + ap.axisV.z * pz;
  /* A's side at offset d from P lands at k·d = d + d·(t / hA) on the face's plane (t = hS − hA,
   * the wall's thickness): the large part d keeps the one rounding of a vertex difference, as
   * the face's own sides do; k·d rounds relative to d, 1e-6 of the window at 10 m. */
  float8 g = ap.thickness.x / ha;
  float8 du0 = ap.openingRect.x - pu, du1 = ap.openingRect.y - pu;
  float8 dv0 = ap.openingRect.z - pv, dv1 = ap.openingRect.w - pv;
  v.u0 = fmax(ap.sourceRect.x - pu, du0 + du0 * g);
  v.u1 = fmin(ap.sourceRect.y - pu, du1 + du1 * g);
  v.v0 = fmax(ap.sourceRect.z - pv, dv0 + dv0 * g);
  v.v1 = fmin(ap.sourceRect.w - pv, dv1 + dv1 * g);
  v.depth = -hs;
  return v;
}

/* Corner i (0..3, counter-clockwise about the emission direction) of the visible rectangle,
 * relative to P. */
inline void aperture_corner8(ApertureView8 v, PnAperture ap, float4 n, int i, float8* x, float8* y,
                             float8* z) {
  float8 u = (i == 0 || i == 3) ? v.u0 : v.u1;
  float8 w = (i < 2) ? v.v0 : v.v1;
  *x = u * ap.axisU.x + w * ap.axisV.x + v.depth * n.x;
  *y = u * ap.axisU.y + w * ap.axisV.y + v.depth * n.y;
  *z = u * ap.axisU.z + w * ap.axisV.z + v.depth * n.z;
}

inline float8 unoccluded_aperture8(ApertureView8 v, PnAperture ap, float4 plane, float8 nx,
                                   float8 ny, float8 nz, const PnEmission* em) {
  HorizonSum8 h;
  horizon_begin8(&h, 0, nx, ny, nz, em);
  float8 ax, ay, az;
  aperture_corner8(v, ap, plane, 0, &ax, &ay, &az);
  float8 ha = nx * ax + ny * ay + nz * az;
  for (int i = 0; i < 4; ++i) {
    float8 bx, by, bz;
    aperture_corner8(v, ap, plane, (i + 1) & 3, &bx, &by, &bz);
    horizon_next8(&h, &ax, &ay, &az, &ha, bx, by, bz, nx, ny, nz);
  }
  return horizon_end8(&h, nx, ny, nz);
}

/* Lanes for which the occluder cannot meet conv(P, visible rectangle): all its vertices lie
 * outside one side plane of that pyramid, by more than eps_length across at their depth. A
 * point x (from P) at depth h towards the face is inside iff u0·h <= x·axisU·hS <= u1·h (and
 * the same in v), hS the face's depth. */
inline int8 misses_aperture_view8(float8 px, float8 py, float8 pz, ApertureView8 v, PnAperture ap,
                                  float4 n, PnOccluder o, const PnSceneTables* tables,
                                  float8 eps_length) {
  float8 hs = -v.depth, margin = eps_length * hs;
  int8 u0 = -1, u1 = -1, v0 = -1, v1 = -1;
  for (int k = 0; k < o.vertexCount; ++k) {
    float4 q = tables->occluderVertices[o.firstVertex + k].hi;
    float8 dx = q.x - px, dy = q.y - py, dz = q.z - pz;
    float8 xu = (ap.axisU.x * dx + ap.axisU.y * dy + ap.axisU.z * dz) * hs;
    float8 xv = (ap.axisV.x * dx + ap.axisV.y * dy + ap.axisV.z * dz) * hs;
    float8 h = -(n.x * dx + n.y * dy + n.z * dz);
    u0 &= xu < v.u0 * h - margin;
    u1 &= xu > v.u1 * h + margin;
    v0 &= xv < v.v0 * h - margin;
    v1 &= xv > v.v1 * h + margin;
    if (!pn_any(u0 | u1 | v0 | v1)) break;
  }
  return u0 | u1 | v0 | v1;
}
