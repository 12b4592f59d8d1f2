/* The contour term of a face whose luminance is a polynomial in the cosine to its axis (a
 * photometric luminaire's opening, docs/method.md "The area model"; Arvo 1995, "Applications of
 * irradiance tensors to the simulation of non-Lambertian phenomena"). The same closed forms as
 * host/reference/cosine_moments.cpp, per boundary arc: for a region V seen from P (unit normal n),
 * the polynomial's axis w (−N for a luminaire's opening, N its emission direction, so that
 * w·ω = cos φ for ω from P towards the face; +z for the overcast sky) and g = w·ω,
 *   M_k = ∫_V g^k (n·ω) dω:  (k + 2) M_k = k (w·n) τ_{k−1} + Σ (n·m) F_k,
 *   τ_k = ∫_V g^k dω:        (k + 1) τ_k = (k − 1) τ_{k−2} + Σ (w·m) F_{k−1},
 * τ_0 = Σ the signed solid angle of the triangle (w, a, b), each arc a → b of angle Θ with
 * m = unit(b × a) (into V) and F_k = ∫_0^Θ f(θ)^k dθ, f(θ) = x cos θ + y sin θ (x = w·â, y = w·t,
 * t the arc's unit tangent at a):
 *   k F_k = (k − 1)(x² + y²) F_{k−2} − [f^{k−1} f′]_0^Θ,   F_0 = Θ.
 * Every M_k is a sum over the arcs, so each arc's share of Σ_k c_k M_k is a term like Lambert's,
 * and the contour paths add it as they add Lambert's: one term per arc, compensated sums. The
 * term returned is 2 Σ_k c_k M_k(arc), which is c_0 Θ (n·m), Lambert's term times c_0, at
 * order 0.
 *
 * Precision (float): the terms of a small or distant face cancel (their sum is of the order of
 * Θ² where each is of the order of Θ), so each must be good to a few roundings of itself, as
 * Lambert's is. The bracket [f^{k−1} f′]_0^Θ is a difference of two nearly equal numbers when Θ
 * is small; it is taken as D_{k−1} f′(Θ) + x^{k−1} (f′(Θ) − y), with D_j = f(Θ)^j − x^j by
 * D_j = f(Θ) D_{j−1} + x^{j−1} (f(Θ) − x), and f(Θ) − x = y sin Θ − x (1 − cos Θ),
 * f′(Θ) − y = −x sin Θ − y (1 − cos Θ), 1 − cos Θ = sin²Θ / (1 + cos Θ) where cos Θ >= 0: each a
 * product of small factors, with no cancellation. A term of order K is then good to about
 * (K + 4) roundings of the largest of its k-th parts, which bounds the error of a face's sum by
 * (K + 4) · 2⁻²⁴ · Σ_arcs Σ_k |c_k| |2 M_k(arc)|; tests/luminaire_area_test.cpp measures it
 * against the host's double. */

#include "prelude.cl"

/* How a face emits, read once per face: order −1 for a uniform luminance (Lambert's term), else
 * the polynomial's order, its axis w and its coefficients. */
typedef struct {
  int order;
  float wx, wy, wz;
  float c[PN_MAX_LUMINANCE_TERMS];
} PnEmission;

inline PnEmission emission_of(PnSourceFace face, const PnSceneTables* tables) {
  PnEmission em;
  em.order = -1;
  em.wx = -face.plane.x;
  em.wy = -face.plane.y;
  em.wz = -face.plane.z;
  if (face.luminance < 0) return em;
  __global const PnLuminancePolynomial* poly = tables->luminances + face.luminance;
  em.order = poly->order;
  em.wx = poly->axis.x;
  em.wy = poly->axis.y;
  em.wz = poly->axis.z;
  for (int k = 0; k < PN_MAX_LUMINANCE_TERMS; ++k) em.c[k] = poly->coefficient[k];
  return em;
}

/* 2 Σ_k c_k M_k over the arc a → b (vectors from P, any length), c = b × a computed to about a
 * rounding of itself by the caller, s = |c| > 0 (lanes with s <= 0 are the caller's to zero). One
 * body for one point (T float, names ending in 1) and eight lanes (float8, 8). */
#define PN_DEFINE_MOMENT_TERM(T, S, Sum, add)                                                    \
  inline T moment_term##S(T ax, T ay, T az, T bx, T by, T bz, T cx, T cy, T cz, T s, T nx, T ny, \
                          T nz, const PnEmission* em) {                                          \
    const float wx = em->wx, wy = em->wy, wz = em->wz;                                           \
    T la = sqrt(ax * ax + ay * ay + az * az), lb = sqrt(bx * bx + by * by + bz * bz);            \
    T ab = ax * bx + ay * by + az * bz;                                                          \
    T theta = atan2(s, ab);                                                                      \
    T inverse = 1.0f / (la * lb);                                                                \
    T sin_t = s * inverse, cos_t = ab * inverse;                                                 \
    T versine = select(1.0f - cos_t, sin_t * sin_t / (1.0f + cos_t), cos_t >= 0.0f);             \
    T mx = cx / s, my = cy / s, mz = cz / s;                                                     \
    T ux = ax / la, uy = ay / la, uz = az / la;                                                  \
    T tx = uy * mz - uz * my, ty = uz * mx - ux * mz, tz = ux * my - uy * mx;                    \
    T x = wx * ux + wy * uy + wz * uz, y = wx * tx + wy * ty + wz * tz;                          \
    T nm = nx * mx + ny * my + nz * mz, wm = wx * mx + wy * my + wz * mz;                        \
    T wn = wx * nx + wy * ny + wz * nz;                                                          \
    T f_end = x * cos_t + y * sin_t, slope_end = y * cos_t - x * sin_t;                          \
    T delta = y * sin_t - x * versine, delta_slope = -x * sin_t - y * versine;                   \
    T r2 = x * x + y * y;                                                                        \
    T wb = (wx * bx + wy * by + wz * bz) / lb;                                                   \
    T omega = 2.0f * atan2((wx * cx + wy * cy + wz * cz) * inverse, 1.0f + x + cos_t + wb);      \
    Sum sum = {em->c[0] * theta * nm, 0.0f}; /* its parts may cancel: compensated */             \
    T f_prev = theta, f_prev2 = 0.0f;        /* F_{k−1}, F_{k−2} */                          \
    T tau_prev = 0.0f, tau_prev2 = 0.0f;     /* τ_{k−2}, τ_{k−3} */                        \
    T d = 0.0f, xp = 1.0f;                   /* D_{k−1}, x^{k−1} */                          \
    for (int k = 1; k <= em->order; ++k) {                                                       \
      const float kf = (float)k;                                                                 \
      T bracket = d * slope_end + xp * delta_slope;                                              \
      T f_k = ((kf - 1.0f) * r2 * f_prev2 - bracket) / kf;                                       \
      T tau = k == 1 ? omega : ((kf - 2.0f) * tau_prev2 + wm * f_prev2) / kf; /* τ_{k−1} */   \
      add(&sum, em->c[k] * (2.0f * (kf * wn * tau + nm * f_k) / (kf + 2.0f)));                   \
      d = f_end * d + xp * delta;                                                                \
      xp *= x;                                                                                   \
      f_prev2 = f_prev;                                                                          \
      f_prev = f_k;                                                                              \
      tau_prev2 = tau_prev;                                                                      \
      tau_prev = tau;                                                                            \
    }                                                                                            \
    return sum.s + sum.c;                                                                        \
  }
PN_DEFINE_MOMENT_TERM(float, 1, PnSum, pn_sum_add)    /* one body for the scalar path */
PN_DEFINE_MOMENT_TERM(float8, 8, PnSum8, pn_sum_add8) /* and for eight lanes */
#undef PN_DEFINE_MOMENT_TERM
