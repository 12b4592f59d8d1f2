/* One boundary arc's term, taken relative to a reference point of its contour, for a face small
 * against its distance from P (lambert.cl, PN_SMALL_FACE; docs/method.md, the precision note), on
 * the unoccluded paths and the penumbra paths alike (contour.cl, PnPieceForm). One body for one
 * point (T float, names ending in 1) and eight lanes (float8, 8).
 *
 * Lambert's term of the arc a → b (vectors from P) is T = θ n·(b × a) / |b × a|, θ the angle
 * between a and b. For a small, distant face each term is of the order of the arc's angle while
 * the contour's terms cancel to E, of the order of the face's angular size squared: a term good
 * to a few roundings of itself leaves an error of the face's angular size in relative precision
 * (1.3e-5 of E for a 0.1 m panel 4 m away). Here every point of a contour is written as C + α, C
 * one point of the contour (per point P and face) and α its offset from C, and with
 * q = θ / |b × a|,
 *   b × a = C × (α − β) + β × α,
 *   T = q n·(β × α) + q n·(C × (α − β)).
 * The second part, taken with q replaced by the constant 1/|C|², sums to zero around a closed
 * contour (the α − β telescope), so each arc contributes
 *   T' = q n·(β × α) + (q − 1/|C|²) n·(C × (α − β)),
 * whose parts are both of the order of (size / distance)², with
 *   q − 1/|C|² = (θ / sin θ − 1) / (|a||b|) + (|C|² − |a||b|) / (|a||b||C|²),
 *   |C|² − |a||b| = (|C|²(|C|² − |b|²) + |b|²(|C|² − |a|²)) / (|C|² + |a||b|),
 *   |C|² − |a|² = −α·(2C + α),
 * θ / sin θ − 1 by its series below 0.5 rad: every factor is computed from the small offsets
 * without cancellation, so T' is good to a few roundings of itself and the sum to a few roundings
 * of E. Where an offset is not small against C (the horizon's chord of a face that the horizon
 * cuts may end far from C) the parts grow and T' is taken as T − n·(C × (α − β)) / |C|², the same
 * number. The telescoping part is dropped on every arc, so an arc whose line passes through P (no
 * term) still gives −n·(C × (α − β)) / |C|².
 *
 * The offsets are vertex differences from the scene's double-float positions, exact to a rounding
 * of themselves however far from P (on the penumbra paths, the visible contour's ends as
 * PnPieceForm takes them). A face of polynomial luminance adds the moment term's powers
 * above 0 (luminance_moments.cl) to c_0 T'. */

#include "luminance_moments.cl"

#define PN_ARC_SMALL_OFFSET 0.25f /* (|α|² + |β|²) / |C|² below which T' is taken in parts */
#define PN_ARC_SERIES_ANGLE 0.5f  /* θ below which θ / sin θ − 1 is taken by its series */

/* x·y − z·w to about one rounding of the result (Kahan's algorithm with fma), where the plain
 * products would leave the rounding of the larger of them (here and in contour.cl). */
#define PN_DEFINE_DIFF_OF_PRODUCTS(T, S)             \
  inline T diff_of_products##S(T x, T y, T z, T w) { \
    T zw = z * w;                                    \
    return fma(x, y, -zw) + fma(-z, w, zw);          \
  }
PN_DEFINE_DIFF_OF_PRODUCTS(float, 1)
PN_DEFINE_DIFF_OF_PRODUCTS(float8, 8)
#undef PN_DEFINE_DIFF_OF_PRODUCTS

/* A contour's reference point C (from P) with |C|² and the contour's spread about it (reach2:
 * the largest squared offset of its points). */
#define PN_DEFINE_CENTRE(T, M, S)                                                   \
  typedef struct {                                                                  \
    T x, y, z, norm2;                                                               \
    T spread; /* the largest offset of the contour's points over |C| (about rad) */ \
  } PnCentre##S;                                                                    \
  inline PnCentre##S pn_centre##S(T x, T y, T z, T reach2) {                        \
    T norm2 = x * x + y * y + z * z;                                                \
    PnCentre##S c = {x, y, z, norm2, sqrt(reach2 / norm2)};                         \
    return c;                                                                       \
  }

/* The azimuth form's Δψ (luminance_moments.cl) relative to C. Δψ = δ(a) − δ(b), δ(p) the
 * azimuth of p about the axis w from C's, tan δ = Y / X with Y = w·(C × α) and X = |C⊥|² + C⊥·α
 * (C⊥ the part of C across w). Its linear part L(p) = Y / |C⊥|² telescopes around a closed
 * contour, so every arc gives up 2 (w·n) W (L(a) − L(b)) (W = Σ_{k>=1} c_k / (k + 2)), and the
 * azimuth form takes Δψ' = R(a) − R(b), R = δ − L = (atan t − t) − Y (C⊥·α) / (X |C⊥|²),
 * t = Y / X, of the order of the arc's angle times the face's, as T' is, where both ends are
 * within 60° of C in azimuth (X > |C⊥|² / 2); otherwise Δψ less the linear part, the same number.
 * Only where the whole contour is off the axis by more than PN_ARC_CLEAR_OF_AXIS (C's angle from
 * w less the contour's spread): the direct form, which an arc takes within 20° of the axis,
 * would have to give up the linear part explicitly, and its parts are not small enough for that;
 * nearer the axis nothing is given up. *dpsi, *drop: as moment_term reads them. */
#define PN_ARC_CLEAR_OF_AXIS 0.42f /* rad (24°) */
#define PN_DEFINE_AZIMUTH_STEP(T, M, S)                                                            \
  inline T whole_azimuth##S(T ax, T ay, T az, T bx, T by, T bz, T kx, T ky, T kz,                  \
                            const PnEmission* em) {                                                \
    const float wx = em->wx, wy = em->wy, wz = em->wz;                                             \
    T qax = wy * az - wz * ay, qay = wz * ax - wx * az, qaz = wx * ay - wy * ax; /* w × a */      \
    T qbx = wy * bz - wz * by, qby = wz * bx - wx * bz, qbz = wx * by - wy * bx; /* w × b */      \
    return atan2(wx * kx + wy * ky + wz * kz, qax * qbx + qay * qby + qaz * qbz);                  \
  }                                                                                                \
  inline T azimuth_rest##S(T y, T x, T u, T cp2) {                                                 \
    T t = y / x, t2 = t * t;                                                                       \
    T series =                                                                                     \
        -t * t2 *                                                                                  \
        (1.0f / 3.0f - t2 * (1.0f / 5.0f - t2 * (1.0f / 7.0f - t2 * (1.0f / 9.0f - t2 / 11.0f)))); \
    T atan_less_t = select(atan(t) - t, series, fabs(t) < 0.25f);                                  \
    return atan_less_t - y * u / (x * cp2);                                                        \
  }                                                                                                \
  inline void azimuth_step##S(const PnCentre##S* c, T ax, T ay, T az, T bx, T by, T bz, T pax,     \
                              T pay, T paz, T pbx, T pby, T pbz, T kx, T ky, T kz, T nx, T ny,     \
                              T nz, const PnEmission* em, T* dpsi, T* drop) {                      \
    const float wx = em->wx, wy = em->wy, wz = em->wz;                                             \
    const float beyond = em->tail[em->order] + em->tail[em->order - 1];                            \
    const T cx = c->x, cy = c->y, cz = c->z;                                                       \
    T whole = whole_azimuth##S(pax, pay, paz, pbx, pby, pbz, kx, ky, kz, em);                      \
    T wc = wx * cx + wy * cy + wz * cz;                                                            \
    T ux = cx - wc * wx, uy = cy - wc * wy, uz = cz - wc * wz; /* C⊥ */                          \
    T cp2 = ux * ux + uy * uy + uz * uz;                                                           \
    M off_axis = atan2(sqrt(cp2), wc) - c->spread > PN_ARC_CLEAR_OF_AXIS;                          \
    T ya = wx * (cy * az - cz * ay) + wy * (cz * ax - cx * az) + wz * (cx * ay - cy * ax);         \
    T yb = wx * (cy * bz - cz * by) + wy * (cz * bx - cx * bz) + wz * (cx * by - cy * bx);         \
    T ua = ux * ax + uy * ay + uz * az, ub = ux * bx + uy * by + uz * bz;                          \
    T xa = cp2 + ua, xb = cp2 + ub;                                                                \
    T linear = (ya - yb) / cp2; /* L(a) − L(b) */                                                \
    M in_reach = (xa > 0.5f * cp2) & (xb > 0.5f * cp2);                                            \
    T rest = azimuth_rest##S(ya, xa, ua, cp2) - azimuth_rest##S(yb, xb, ub, cp2);                  \
    T wn = wx * nx + wy * ny + wz * nz;                                                            \
    *dpsi = select(whole, select(whole - linear, rest, in_reach), off_axis);                       \
    *drop = select((T)(0.0f), 2.0f * wn * beyond * linear, off_axis);                              \
  }

/* T' of the arc C + α → C + β (above) for a uniform luminance, or 2 Σ_k c_k M_k with c_0 T' for
 * a polynomial one (em). */
#define PN_DEFINE_ARC_TERM(T, M, S)                                                                \
  inline T arc_term##S(const PnCentre##S* c, T ax, T ay, T az, T bx, T by, T bz, T nx, T ny, T nz, \
                       const PnEmission* em) {                                                     \
    const T cx = c->x, cy = c->y, cz = c->z, c2 = c->norm2;                                        \
    T pax = cx + ax, pay = cy + ay, paz = cz + az; /* a = C + α */                                \
    T pbx = cx + bx, pby = cy + by, pbz = cz + bz; /* b = C + β */                                \
    T kx = diff_of_products##S(pby, paz, pbz, pay), ky = diff_of_products##S(pbz, pax, pbx, paz),  \
      kz = diff_of_products##S(pbx, pay, pby, pax); /* b × a */                                   \
    T s = sqrt(kx * kx + ky * ky + kz * kz);                                                       \
    T theta = atan2(s, pax * pbx + pay * pby + paz * pbz);                                         \
    T la2 = pax * pax + pay * pay + paz * paz, lb2 = pbx * pbx + pby * pby + pbz * pbz;            \
    T lab = sqrt(la2 * lb2);                                                                       \
    T q = theta / s;                                                                               \
    T dx = ax - bx, dy = ay - by, dz = az - bz; /* α − β */                                    \
    T g = nx * (cy * dz - cz * dy) + ny * (cz * dx - cx * dz) + nz * (cx * dy - cy * dx);          \
    T f = nx * (by * az - bz * ay) + ny * (bz * ax - bx * az) + nz * (bx * ay - by * ax);          \
    T t2 = theta * theta;                                                                          \
    T excess =                                                                                     \
        select(theta * lab / s - 1.0f,                                                             \
               t2 * (1.0f / 6.0f +                                                                 \
                     t2 * (7.0f / 360.0f + t2 * (31.0f / 15120.0f + t2 * (127.0f / 604800.0f)))),  \
               theta < PN_ARC_SERIES_ANGLE); /* θ / sin θ − 1 */                               \
    T near_a = -(ax * (2.0f * cx + ax) + ay * (2.0f * cy + ay) + az * (2.0f * cz + az));           \
    T near_b = -(bx * (2.0f * cx + bx) + by * (2.0f * cy + by) + bz * (2.0f * cz + bz));           \
    T lengths = (c2 * near_b + lb2 * near_a) / (c2 + lab); /* |C|² − |a||b| */                  \
    T centred = q * f + (excess / lab + lengths / (lab * c2)) * g;                                 \
    T classic = q * (nx * kx + ny * ky + nz * kz) - g / c2;                                        \
    M small =                                                                                      \
        ax * ax + ay * ay + az * az + bx * bx + by * by + bz * bz < PN_ARC_SMALL_OFFSET * c2;      \
    M none = s <= 0.0f;                                                                            \
    T lambert = select(select(classic, centred, small), -g / c2, none);                            \
    if (em->order < 0) return lambert;                                                             \
    T dpsi = 0.0f, drop = 0.0f;                                                                    \
    if (em->order > PN_MOMENT_DIRECT_ORDER)                                                        \
      azimuth_step##S(c, ax, ay, az, bx, by, bz, pax, pay, paz, pbx, pby, pbz, kx, ky, kz, nx, ny, \
                      nz, em, &dpsi, &drop);                                                       \
    const PnArcShares##S shares = {lambert, dpsi, drop};                                           \
    return select(                                                                                 \
        moment_term##S(pax, pay, paz, pbx, pby, pbz, kx, ky, kz, s, nx, ny, nz, &shares, em, 0),   \
        em->c[0] * lambert - drop, none);                                                          \
  }

#define PN_DEFINE_ARC_TWINS(T, M, S) \
  PN_DEFINE_CENTRE(T, M, S)          \
  PN_DEFINE_AZIMUTH_STEP(T, M, S)    \
  PN_DEFINE_ARC_TERM(T, M, S)
PN_DEFINE_ARC_TWINS(float, int, 1)   /* one body for the scalar path */
PN_DEFINE_ARC_TWINS(float8, int8, 8) /* and for eight lanes */
#undef PN_DEFINE_ARC_TWINS
#undef PN_DEFINE_CENTRE
#undef PN_DEFINE_AZIMUTH_STEP
#undef PN_DEFINE_ARC_TERM
