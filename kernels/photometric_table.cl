/* A luminaire's intensity towards a direction of its local frame (docs/photometry.md): the
 * table's angles of the direction, then bilinear interpolation in the two angles, in float, as
 * host/photometry/light_distribution.cpp does in double. At a node the weights are 1 and 0, so
 * the table's value comes back; outside the measured range the intensity is 0.
 *
 * One difference from the host, on purpose: an angle within PN_EPS_REL × 180° of an end of its
 * axis counts as that end. Float angles carry errors of about 1e-5°, and a point level with a
 * downlight measured to γ = 90° must not flip between the table's last value and 0 by rounding. */

#include "prelude.cl"

/* i with axis[i] <= x <= axis[i + 1] and t, the weight of axis[i + 1]; false outside the axis
 * (beyond the end tolerance). A single angle holds only at itself. */
inline bool pn_locate_angle(__global const float* axis, int n, float x, int* i, float* t) {
  const float end_tolerance = PN_EPS_REL * 180.0f;
  if (n == 1) {
    *i = 0;
    *t = 0.0f;
    return fabs(x - axis[0]) <= end_tolerance;
  }
  if (x < axis[0] && axis[0] - x <= end_tolerance) x = axis[0];
  if (x > axis[n - 1] && x - axis[n - 1] <= end_tolerance) x = axis[n - 1];
  if (!(x >= axis[0] && x <= axis[n - 1])) return false;
  int lo = 0, hi = n - 1; /* axis[lo] <= x; the cell found is the host's upper_bound - 1 */
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    if (axis[mid] <= x)
      lo = mid;
    else
      hi = mid;
  }
  *i = lo;
  *t = (x - axis[lo]) / (axis[lo + 1] - axis[lo]);
  return true;
}

/* The table's value along plane `plane` at in-plane cell (k, s). */
inline float pn_along_plane(PnCandelaTable table, __global const float* candela, int plane, int k,
                            float s) {
  const int n = table.inPlaneCount;
  const float a = candela[table.firstCandela + plane * n + k];
  if (s == 0.0f || n == 1) return a;
  return (1.0f - s) * a + s * candela[table.firstCandela + plane * n + k + 1];
}

/* cd at the table's own angles: the plane angle (C, V or H) and the in-plane one (γ, H or V). */
inline float pn_table_interpolate(PnCandelaTable table, __global const float* angles,
                                  __global const float* candela, float plane_deg,
                                  float in_plane_deg) {
  __global const float* planes = angles + table.firstAngle;
  __global const float* in_plane = planes + table.planeCount;
  int k = 0;
  float s = 0.0f;
  if (!pn_locate_angle(in_plane, table.inPlaneCount, in_plane_deg, &k, &s)) return 0.0f;
  const bool periodic = table.type == PN_PHOTOMETRIC_C;
  const int m = table.planeCount;
  if (m == 1)
    return (periodic || plane_deg == planes[0]) ? pn_along_plane(table, candela, 0, k, s) : 0.0f;
  int j = 0;
  float t = 0.0f;
  if (periodic && (plane_deg >= planes[m - 1] || plane_deg < planes[0])) {
    /* after the last plane comes the first again, 360° further on */
    const float start = planes[m - 1];
    const float gap = planes[0] + 360.0f - start;
    const float offset = plane_deg >= start ? plane_deg - start : plane_deg + 360.0f - start;
    t = offset / gap;
    const float a = pn_along_plane(table, candela, m - 1, k, s);
    return t == 0.0f ? a : (1.0f - t) * a + t * pn_along_plane(table, candela, 0, k, s);
  }
  if (!pn_locate_angle(planes, m, plane_deg, &j, &t)) return 0.0f;
  const float a = pn_along_plane(table, candela, j, k, s);
  return t == 0.0f ? a : (1.0f - t) * a + t * pn_along_plane(table, candela, j + 1, k, s);
}

/* cd towards the local direction d (need not be unit, must not be zero). The angles as
 * host/photometry/photometric_frame.cpp defines them:
 *   type C: γ = atan2(|d_xy|, -d_z), C = atan2(d_y, d_x) in [0, 360)
 *   type B: H = atan2(d_y, |d_xz|), V = atan2(d_x, -d_z); planes V, in-plane H
 *   type A: V = atan2(d_x, |d_yz|), H = atan2(d_y, -d_z); planes H, in-plane V
 * atan2pi keeps the angle's relative precision through the conversion to degrees. */
inline float pn_table_intensity(PnCandelaTable table, __global const float* angles,
                                __global const float* candela, float3 d) {
  float plane_deg, in_plane_deg;
  if (table.type == PN_PHOTOMETRIC_C) {
    in_plane_deg = 180.0f * atan2pi(hypot(d.x, d.y), -d.z);
    plane_deg = 180.0f * atan2pi(d.y, d.x);
    if (plane_deg < 0.0f) plane_deg += 360.0f;
    if (plane_deg >= 360.0f) plane_deg = 0.0f;
  } else if (table.type == PN_PHOTOMETRIC_B) {
    in_plane_deg = 180.0f * atan2pi(d.y, hypot(d.x, d.z));
    plane_deg = 180.0f * atan2pi(d.x, -d.z);
  } else {
    in_plane_deg = 180.0f * atan2pi(d.x, hypot(d.y, d.z));
    plane_deg = 180.0f * atan2pi(d.y, -d.z);
  }
  return pn_table_interpolate(table, angles, candela, plane_deg, in_plane_deg);
}
