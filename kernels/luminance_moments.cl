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
 * against the host's double.
 *
 * High powers (a narrow beam's nonnegative fit, order above PN_MOMENT_DIRECT_ORDER): an arc's F_k
 * and τ_k by the recurrences above do not shrink as g^k does over the region. τ_k holds the
 * triangle from w, and the forward recurrence of F_k grows as r^k (r = √(x² + y²), the largest g on
 * the arc's whole great circle) where the arc itself sees g <= g_max < r: each arc's part of a high
 * power is then of the order of c_k Θ however little of it the region sees, and its rounding is
 * many times E where the spill light dominates. Each arc's term is the same number written about
 * the azimuth ψ about w (Arvo's τ_k by the divergence theorem in ψ):
 *   k τ_{k−1} = Δψ − A_k,   A_k = ∫_arc g^k dψ = (w·m) Σ_{i>=0} F_{k+2i},
 * Δψ the arc's azimuth about w (the terms Δψ sum to 2π or 0 around the region), so that
 *   2 Σ_k c_k M_k = c_0 Θ (n·m) + 2 [(w·n) Δψ Σ_{k>=1} c_k/(k+2)
 *                                   + Σ_{j>=1} F_j ((n·m) c_j/(j+2) − (w·n)(w·m) W_j)],
 * W_j = Σ c_k/(k+2) over 1 <= k <= j of j's parity: every part now shrinks with g^j over the arc,
 * the Δψ part being Lambert's kind (one rounding of an arc's angle). The F_j are taken backward
 * from F = 0 beyond the order, F_{j−2} = (j F_j + [f^{j−1} f′]_0^Θ) / ((j − 1) r²), which damps the
 * start's error by (g_max / r)² a step, where the arc misses its circle's peak by g_max <=
 * PN_MOMENT_RATIO r (the bracket as x^{j−1} (expm1((j − 1) log1p((f(Θ) − x) / x)) f′(Θ) + f′(Θ) −
 * y), without cancellation; exact every PN_MOMENT_EXACT_EVERY steps, stepped down by 1/x and ((·) −
 * (ρ − 1)) / ρ, ρ = f(Θ) / x, between, which multiplies its error by 1/ρ a step: where ρ < 0.9,
 * f(Θ)^{j−1} − x^{j−1} with each power stepped alone); forward, as above, where the arc holds the
 * peak or nearly and r <= PN_MOMENT_RATIO. The sum over j is cut where that ratio (g_max / r, or r,
 * each at least g_max) to the power beyond the order is PN_MOMENT_CUT, at most PN_MOMENT_MAX_TAIL
 * powers beyond (the lanes' largest need: an arc far off the axis needs a few dozen). Arcs near the
 * axis (both ratios above PN_MOMENT_RATIO, where the beam dominates E) keep the recurrences above.
 * Each way gives the arc's own exact term, so the arcs of one region may mix them. */

#include "prelude.cl"

#define PN_MOMENT_DIRECT_ORDER 12 /* the highest order without the azimuth form */
#define PN_MOMENT_RATIO 0.97f     /* the largest g_max / r (backward) or r (forward) taken */
#define PN_MOMENT_CUT 1.0e-8f     /* the ratio's power where the powers are cut off */
#define PN_MOMENT_MAX_TAIL 640    /* ln(PN_MOMENT_CUT) / ln(PN_MOMENT_RATIO) = 605 */
#define PN_MOMENT_EXACT_EVERY 32  /* steps between exact powers in the backward sweep (2^n) */

/* The largest of the lanes. */
inline float __attribute__((overloadable)) pn_lane_max(float v) {
  return v;
}
inline float __attribute__((overloadable)) pn_lane_max(float8 v) {
  float4 a = fmax(v.lo, v.hi);
  float2 b = fmax(a.lo, a.hi);
  return fmax(b.x, b.y);
}

/* How a face emits, read once per face: order −1 for a uniform luminance (Lambert's term), else
 * the polynomial's order, its axis w and its coefficients. */
typedef struct {
  int order;
  float wx, wy, wz;
  float c[PN_MAX_LUMINANCE_TERMS];
  float tail[PN_MAX_LUMINANCE_TERMS]; /* W_j = Σ c_k/(k + 2), 1 <= k <= j, k of j's parity */
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
  for (int k = 0; k < PN_MAX_LUMINANCE_TERMS; ++k) {
    em.c[k] = poly->coefficient[k];
    em.tail[k] = (k >= 2 ? em.tail[k - 2] : 0.0f) + (k >= 1 ? em.c[k] / (float)(k + 2) : 0.0f);
  }
  return em;
}

/* An arc's parts that a caller takes relative to its contour's reference point (arc_term.cl,
 * for a small, distant face): `lambert` its Lambert term, `dpsi` the azimuth form's Δψ and `drop`
 * what the direct form gives up for it (each less a part that telescopes around the contour). A
 * null pointer: every part from the arc alone. */
typedef struct {
  float lambert, dpsi, drop;
} PnArcShares1;
typedef struct {
  float8 lambert, dpsi, drop;
} PnArcShares8;

/* The azimuth form of one arc's term (above) where it is the more accurate, else `direct`, the
 * term by the recurrences of F_k and τ_k. x, y, r2, f_end = f(Θ), slope_end = f′(Θ), delta =
 * f(Θ) − x and delta_slope = f′(Θ) − y as moment_term computes them; c = b × a; shares (or null)
 * and azimuth_lanes (or null) as moment_term's. */
#define PN_DEFINE_AZIMUTH_FORM(T, M, S)                                                                           \
  inline T azimuth_form##S(T direct, T theta, T x, T y, T r2, T f_end, T slope_end, T delta,                      \
                           T delta_slope, T nm, T wm, T wn, T ax, T ay, T az, T bx, T by, T bz,                   \
                           T cx, T cy, T cz, const PnArcShares##S* shares, const PnEmission* em,                  \
                           M* azimuth_lanes) {                                                                    \
    const float wx = em->wx, wy = em->wy, wz = em->wz;                                                            \
    const int order = em->order;                                                                                  \
    const float far_even = em->tail[order - (order & 1)],                                                         \
                far_odd = em->tail[order - 1 + (order & 1)];                                                      \
    const float beyond = em->tail[order] + em->tail[order - 1]; /* Σ_{k>=1} c_k/(k+2) */                         \
    T r = sqrt(r2), g_max = fmax(x, f_end);                                                                       \
    M holds_peak = (y > 0.0f) & (slope_end < 0.0f);                                                               \
    M backward = !holds_peak & (g_max <= PN_MOMENT_RATIO * r) & (x > 0.0f) & (f_end > 0.0f);                      \
    M forward = !backward & (r <= PN_MOMENT_RATIO);                                                               \
    if (azimuth_lanes) *azimuth_lanes = backward | forward;                                                       \
    if (!pn_any(backward | forward)) return direct;                                                               \
    /* The powers beyond the order each lane needs: its ratio (g_max / r backward, r forward,                     \
     * both bounding g_max) to that power is PN_MOMENT_CUT. */                                                    \
    /* Each sweep runs as far as its lanes' largest need. */                                                      \
    T need_ahead = select((T)(0.0f), log(PN_MOMENT_CUT) / log(fmax(r, 1e-3f)), forward);                          \
    T need_behind = select((T)(0.0f), log(PN_MOMENT_CUT) / log(fmax(g_max / r, 1e-3f)), backward);                \
    const int last_ahead =                                                                                        \
        order + 2 + (int)fmin(pn_lane_max(need_ahead), (float)PN_MOMENT_MAX_TAIL);                                \
    const int last_behind =                                                                                       \
        order + 2 + (int)fmin(pn_lane_max(need_behind), (float)PN_MOMENT_MAX_TAIL);                               \
    /* Δψ, the azimuth from a to b about w: the angle from w × a to w × b, signed by w·(b × a). */          \
    T pax = wy * az - wz * ay, pay = wz * ax - wx * az, paz = wx * ay - wy * ax;                                  \
    T pbx = wy * bz - wz * by, pby = wz * bx - wx * bz, pbz = wx * by - wy * bx;                                  \
    T dpsi = shares ? shares->dpsi                                                                                \
                    : atan2(wx * cx + wy * cy + wz * cz, pax * pbx + pay * pby + paz * pbz);                      \
    T wnm = wn * wm;                                                                                              \
    /* Forward: F_j for j = 1..last_ahead, as moment_term. */                                                     \
    T ahead = 0.0f;                                                                                               \
    if (pn_any(forward)) {                                                                                        \
      T f_prev = theta, f_prev2 = 0.0f, d = 0.0f, xp = 1.0f;                                                      \
      for (int j = 1; j <= last_ahead; ++j) {                                                                     \
        const float jf = (float)j;                                                                                \
        T f_j = ((jf - 1.0f) * r2 * f_prev2 - (d * slope_end + xp * delta_slope)) / jf;                           \
        const float cj = j <= order ? em->c[j] / (jf + 2.0f) : 0.0f;                                              \
        const float wj = j <= order ? em->tail[j] : ((j & 1) ? far_odd : far_even);                               \
        ahead += f_j * (nm * cj - wnm * wj);                                                                      \
        d = f_end * d + xp * delta;                                                                               \
        xp *= x;                                                                                                  \
        f_prev2 = f_prev;                                                                                         \
        f_prev = f_j;                                                                                             \
      }                                                                                                           \
    }                                                                                                             \
    /* Backward: F_{j−2} from F_j, both parities, from F = 0 at last_behind and the one below. */               \
    T behind = 0.0f;                                                                                              \
    if (pn_any(backward)) {                                                                                       \
      T f_hi = 0.0f, f_lo = 0.0f; /* F_j, F_{j−1} */                                                            \
      T inverse_r2 = 1.0f / r2;                                                                                   \
      T log_ratio =                                                                                               \
          log1p(delta / x); /* f(Θ)^{j−1} − x^{j−1} = x^{j−1} expm1((j − 1) log_ratio) */              \
      /* x^{j−1}, and f(Θ)^{j−1} − x^{j−1} = x^{j−1} ((f(Θ)/x)^{j−1} − 1) (`spread`), kept as the \
       * product (far down the tail x^{j−1} underflows where (f(Θ)/x)^{j−1} overflows; f(Θ)^{j−1}         \
       * is then taken by pown, x^{j−1} below FLT_MIN leaving no cancellation that matters).                    \
       * Stepped down, ρ^{j−1} − 1 multiplies its error by 1/ρ a step (ρ = f(Θ)/x): where ρ < 0.9        \
       * the difference of the two powers, each stepped alone, is taken instead (no cancellation                  \
       * that costs more than a factor 5 there). */                                                               \
      T power = 0.0f, spread = 0.0f, power_end = 0.0f;                                                            \
      T inverse_x = 1.0f / x, ratio_less_1 = expm1(log_ratio), inverse_ratio = exp(-log_ratio);                   \
      const M apart = log_ratio < -0.10536f; /* ρ < 0.9 */                                                       \
      const T inverse_end = 1.0f / f_end;                                                                         \
      for (int j = last_behind; j >= 3; --j) {                                                                    \
        const float jf = (float)j;                                                                                \
        if (((last_behind - j) & (PN_MOMENT_EXACT_EVERY - 1)) == 0) {                                             \
          power = pown(x, (M)(j - 1));                                                                            \
          spread = power * expm1((jf - 1.0f) * log_ratio);                                                        \
          power_end = power + spread;                                                                             \
          const M lost = (M)(!isfinite(spread)) | (M)(power < FLT_MIN);                                           \
          if (pn_any(lost)) {                                                                                     \
            /* f(Θ)^{j−1}: below x^{j−1}, under FLT_MIN, where f(Θ) <= x: 0 there, at no pown */            \
            const T exact_end =                                                                                   \
                pn_any(lost & (M)(log_ratio > 0.0f)) ? pown(f_end, (M)(j - 1)) : (T)(0.0f);                       \
            power_end = select(power_end, exact_end, lost);                                                       \
            spread = select(spread, exact_end - power, lost);                                                     \
          }                                                                                                       \
        }                                                                                                         \
        T bracket = select(spread, power_end - power, apart) * slope_end + power * delta_slope;                   \
        T f_j2 = (jf * f_hi + bracket) * inverse_r2 / (jf - 1.0f); /* F_{j−2} */                                \
        const int i = j - 2;                                                                                      \
        const float ci = i <= order ? em->c[i] / ((float)i + 2.0f) : 0.0f;                                        \
        const float wi = i <= order ? em->tail[i] : ((i & 1) ? far_odd : far_even);                               \
        behind += f_j2 * (nm * ci - wnm * wi);                                                                    \
        f_hi = f_lo;                                                                                              \
        f_lo = f_j2;                                                                                              \
        /* ρ^{j−2} − 1 = (ρ^{j−1} − 1 − (ρ − 1)) / ρ, times x^{j−2} */                          \
        spread = (spread - power * ratio_less_1) * inverse_x * inverse_ratio;                                     \
        power *= inverse_x; /* x^{j−2} */                                                                       \
        power_end *= inverse_end;                                                                                 \
      }                                                                                                           \
      /* behind holds j − 2 = 1..last_behind − 2; the two highest powers, whose F start at 0, are             \
       * the cut-off's. */                                                                                        \
    }                                                                                                             \
    T rest = 2.0f * (wn * dpsi * beyond + select(ahead, behind, backward));                                       \
    T azimuth = shares ? em->c[0] * shares->lambert + rest : em->c[0] * theta * nm + rest;                        \
    return select(direct, azimuth, backward | forward);                                                           \
  }
PN_DEFINE_AZIMUTH_FORM(float, int, 1)
PN_DEFINE_AZIMUTH_FORM(float8, int8, 8)
#undef PN_DEFINE_AZIMUTH_FORM

/* 2 Σ_k c_k M_k over the arc a → b (vectors from P, any length), c = b × a computed to about a
 * rounding of itself by the caller, s = |c| > 0 (lanes with s <= 0 are the caller's to zero);
 * `shares`, where not null, the parts the caller takes relative to its contour's reference point
 * (c_0's part is then c_0 shares->lambert); `azimuth_lanes`, where not null, receives the lanes
 * that took the azimuth form (none at orders up to PN_MOMENT_DIRECT_ORDER). One body for one point
 * (T float, names ending in 1) and eight lanes (float8, 8). */
#define PN_DEFINE_MOMENT_TERM(T, M, S, Sum, add)                                                  \
  inline T moment_term##S(T ax, T ay, T az, T bx, T by, T bz, T cx, T cy, T cz, T s, T nx, T ny,  \
                          T nz, const PnArcShares##S* shares, const PnEmission* em,               \
                          M* azimuth_lanes) {                                                     \
    if (azimuth_lanes) *azimuth_lanes = 0;                                                        \
    const float wx = em->wx, wy = em->wy, wz = em->wz;                                            \
    T la = sqrt(ax * ax + ay * ay + az * az), lb = sqrt(bx * bx + by * by + bz * bz);             \
    T ab = ax * bx + ay * by + az * bz;                                                           \
    T theta = atan2(s, ab);                                                                       \
    T inverse = 1.0f / (la * lb);                                                                 \
    T sin_t = s * inverse, cos_t = ab * inverse;                                                  \
    T versine = select(1.0f - cos_t, sin_t * sin_t / (1.0f + cos_t), cos_t >= 0.0f);              \
    T mx = cx / s, my = cy / s, mz = cz / s;                                                      \
    T ux = ax / la, uy = ay / la, uz = az / la;                                                   \
    T tx = uy * mz - uz * my, ty = uz * mx - ux * mz, tz = ux * my - uy * mx;                     \
    T x = wx * ux + wy * uy + wz * uz, y = wx * tx + wy * ty + wz * tz;                           \
    T nm = nx * mx + ny * my + nz * mz, wm = wx * mx + wy * my + wz * mz;                         \
    T wn = wx * nx + wy * ny + wz * nz;                                                           \
    T f_end = x * cos_t + y * sin_t, slope_end = y * cos_t - x * sin_t;                           \
    T delta = y * sin_t - x * versine, delta_slope = -x * sin_t - y * versine;                    \
    T r2 = x * x + y * y;                                                                         \
    T wb = (wx * bx + wy * by + wz * bz) / lb;                                                    \
    T omega = 2.0f * atan2((wx * cx + wy * cy + wz * cz) * inverse, 1.0f + x + cos_t + wb);       \
    Sum sum = {shares ? em->c[0] * shares->lambert : em->c[0] * theta * nm,                       \
               0.0f};                    /* its parts may cancel: compensated */                  \
    T f_prev = theta, f_prev2 = 0.0f;    /* F_{k−1}, F_{k−2} */                               \
    T tau_prev = 0.0f, tau_prev2 = 0.0f; /* τ_{k−2}, τ_{k−3} */                             \
    T d = 0.0f, xp = 1.0f;               /* D_{k−1}, x^{k−1} */                               \
    for (int k = 1; k <= em->order; ++k) {                                                        \
      const float kf = (float)k;                                                                  \
      T bracket = d * slope_end + xp * delta_slope;                                               \
      T f_k = ((kf - 1.0f) * r2 * f_prev2 - bracket) / kf;                                        \
      T tau = k == 1 ? omega : ((kf - 2.0f) * tau_prev2 + wm * f_prev2) / kf; /* τ_{k−1} */    \
      add(&sum, em->c[k] * (2.0f * (kf * wn * tau + nm * f_k) / (kf + 2.0f)));                    \
      d = f_end * d + xp * delta;                                                                 \
      xp *= x;                                                                                    \
      f_prev2 = f_prev;                                                                           \
      f_prev = f_k;                                                                               \
      tau_prev2 = tau_prev;                                                                       \
      tau_prev = tau;                                                                             \
    }                                                                                             \
    if (em->order <= PN_MOMENT_DIRECT_ORDER) return sum.s + sum.c;                                \
    T direct = shares ? (sum.s + sum.c) - shares->drop : sum.s + sum.c;                           \
    return azimuth_form##S(direct, theta, x, y, r2, f_end, slope_end, delta, delta_slope, nm, wm, \
                           wn, ax, ay, az, bx, by, bz, cx, cy, cz, shares, em, azimuth_lanes);    \
  }
PN_DEFINE_MOMENT_TERM(float, int, 1, PnSum, pn_sum_add)     /* one body for the scalar path */
PN_DEFINE_MOMENT_TERM(float8, int8, 8, PnSum8, pn_sum_add8) /* and for eight lanes */
#undef PN_DEFINE_MOMENT_TERM
