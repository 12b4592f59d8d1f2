/* The contour term of a face seen from near its own plane, taken in that plane (docs/method.md,
 * the precision note: "A face seen from near its own plane"). For a point P at height h above
 * the plane of a face whose luminance is a polynomial in g, the cosine from the face's normal N
 * (uniform: order 0; a luminaire's opening: its fitted powers), F = P − hN the foot of P on the
 * plane and ρ = y − F for a point y of the visible region R (r² = ρ² + h²):
 *   M_k = ∫_R g^k (n·ω) dω = h^{k+1} ∫_R (n·ρ − h n·N) / r^{k+4} dA.
 * Per edge of R (t its unit direction, m = t × N, d = m·A the signed distance of F from its
 * line, τ the position along the line from the foot of the perpendicular, D² = d² + h²) and
 * p = k + 2:
 * - the in-plane part, by the divergence theorem: J_p = h^{p−1} ∫ dτ / (τ² + D²)^{p/2},
 *   J_2 = h θ / D (θ the angle the edge subtends at P), J_3 = (h²/D²) [τ / r]_A^B,
 *   J_{p+2} = (h²/D²) ([(τ / r) g^{p−1}]_A^B / p + (p − 1) J_p / p);
 * - the part along N, over the triangle (F, A, B) in the azimuth ψ about F:
 *   h^p ∫ dA / r^{p+2} = (Δψ − A_p) / p,  A_p = ∫_edge g^p dψ = A_{p−2} − (d/h) J_p
 *   (A_0 = Δψ, A_1 = [atan(h τ / (d r))]_A^B), or, summed from the other end,
 *   A_p = (d/h) Σ_{j>=1} J_{p+2j}, whose terms shrink as (h²/D²)^j;
 * so that 2 M_k(edge) = −(2/p) (n·m J_p + (n·N)(Δψ − A_p)).
 *
 * Why: Lambert's terms of a face seen edge-on are each of the order of the edge's angle while
 * their sum is of the order of h² (the part along N) or h (the rest), so their rounding grows as
 * 1/sin²e of E, e the elevation above the face's plane. Here the edges' Δψ sum to 2π times the
 * contour's winding about F, taken as that (planar_closing8); every other part carries its power
 * of h itself: A_p as the tail sum where h²/D² <= PN_PLANAR_TAIL_RATIO (in closed form for
 * uniform luminance), forward above it, where g is not small and nothing cancels much. A narrow
 * beam's powers above PN_MOMENT_DIRECT_ORDER keep the moment term's azimuth form, whose parts
 * shrink with g^k over the arc, less its Δψ part, which is the same Δψ about F and joins the
 * closing. h comes from the double-float positions to a rounding of itself (planar_height8); the
 * in-plane coordinates need only a rounding of the distance. Eight lanes. */

#include "luminance_moments.cl"

#define PN_PLANAR_TAIL_RATIO 0.25f /* h²/D² at most where A_p is the tail sum */
#define PN_PLANAR_TAIL 14          /* tail terms: 0.25^14 = 3.7e-9 */
#define PN_PLANAR_ALONG_N 1e-5f    /* b − a along N beyond which that part is taken out */
#define PN_PLANAR_MAX_P (PN_MOMENT_DIRECT_ORDER + 2 + 2 * PN_PLANAR_TAIL)

/* Whether the planar form serves a face: uniform luminance, or a polynomial about −N (a
 * luminaire's opening). */
inline bool planar_emission(PnSourceFace face, const PnEmission* em) {
  if (em->order < 0) return true;
  return em->wx * face.plane.x + em->wy * face.plane.y + em->wz * face.plane.z < -0.9999995f;
}

/* The lanes that see a face near its plane: P's height above the plane below a sine times its
 * distance from vertex 0 (x, y, z from P). Lambert's terms there lose as 1/sin²e (above); higher
 * they keep E within the kernel's 1e-5 as the planar form does, at a third of its cost per edge:
 * up to 20° for uniform luminance (PN_PLANAR_SINE_UNIFORM), whose terms are Lambert's alone, and
 * 30° for a polynomial (PN_PLANAR_SINE), whose higher powers' terms lose more (measured by
 * tests/near_plane_test.cpp: at 20-30° with Lambert's terms, up to 8e-6 of E uniform and 2.0e-5
 * for a power 9). The planar form at 20-30° costs a work plane under ceiling panels a third more
 * kernel time. The penumbra paths take the crossings of their visible contour's edges in the
 * plane (`crossings`: contour.cl, planar_crossing) up to 30° for every luminance: at 20-25° past a
 * bezel, the side planes' crossing directions moved E by up to 2.3e-5 of the unoccluded E, the
 * lines' crossings in the plane by 6.5e-6. From vertex 0's offset, as every other choice of form:
 * a lane's E does not depend on the scene's origin (the positions' hi/lo split), nor on the lanes
 * beside it, and every path switches alike. */
#define PN_PLANAR_SINE_UNIFORM 0.35f
#define PN_PLANAR_SINE 0.5f

/* Whether the planar form keeps an occluder's ends' heights from the double-float positions
 * (planar_depth): for a face off the scene's axes. */
inline bool planar_heights_kept(float4 plane) {
  return (plane.x == 0.0f) + (plane.y == 0.0f) + (plane.z == 0.0f) < 2;
}

/* What the planar form needs of a face per lane: P's height h above the face's plane, n·N, the
 * plane's normal N, and the running sum of the edges' Δψ. */
#define PN_DEFINE_PLANAR_FRAME(T, M, S, Sum, add)                                                          \
  inline M planar_lanes##S(PnSourceFace face, const PnEmission* em, T x, T y, T z,                         \
                           bool crossings) {                                                               \
    if (!planar_emission(face, em)) return (M)(0);                                                         \
    const T h = -(face.plane.x * x + face.plane.y * y + face.plane.z * z);                                 \
    const float sine = em->order <= 0 && !crossings ? PN_PLANAR_SINE_UNIFORM : PN_PLANAR_SINE;             \
    return h * h < sine * sine * (x * x + y * y + z * z);                                                  \
  }                                                                                                        \
  typedef struct {                                                                                         \
    T h, nn, dpsi_sum;                                                                                     \
    float3 n;                                                                                              \
  } PnPlanarFrame##S;                                                                                      \
  /* h = N·(P − V0), V0 the face's first vertex and P at (px, py, pz) + (lx, ly, lz): V0 − P per      \
   * coordinate as an unevaluated sum (TwoSum of the hi parts, plus the lo parts), each product's          \
   * rounding kept by fma, so that h is good to a rounding of itself however far P is from the             \
   * face. */                                                                                              \
  inline T planar_height##S(T px, T py, T pz, T lx, T ly, T lz, PnSourceFace face,                         \
                            const PnSceneTables* tables) {                                                 \
    const PnPosition v = tables->sourceVertices[face.firstVertex];                                         \
    const float3 n = face.plane.xyz;                                                                       \
    const T sx = v.hi.x - px, sy = v.hi.y - py, sz = v.hi.z - pz;                                          \
    const T bx = sx - v.hi.x, by = sy - v.hi.y, bz = sz - v.hi.z;                                          \
    const T ex = (v.hi.x - (sx - bx)) + (-px - bx) + (v.lo.x - lx);                                        \
    const T ey = (v.hi.y - (sy - by)) + (-py - by) + (v.lo.y - ly);                                        \
    const T ez = (v.hi.z - (sz - bz)) + (-pz - bz) + (v.lo.z - lz);                                        \
    const T qx = n.x * sx, qy = n.y * sy, qz = n.z * sz;                                                   \
    Sum sum = {0.0f, 0.0f};                                                                                \
    add(&sum, qx);                                                                                         \
    add(&sum, qy);                                                                                         \
    add(&sum, qz);                                                                                         \
    const T rest = (fma((T)(n.x), sx, -qx) + n.x * ex) + (fma((T)(n.y), sy, -qy) + n.y * ey) +             \
                   (fma((T)(n.z), sz, -qz) + n.z * ez);                                                    \
    return -(sum.s + (sum.c + rest));                                                                      \
  }                                                                                                        \
  /* The planar frame of a face for P (as planar_height) with unit normal (nx, ny, nz). */                 \
  inline PnPlanarFrame##S planar_frame_at##S(T px, T py, T pz, T lx, T ly, T lz, T nx, T ny, T nz,         \
                                             PnSourceFace face, const PnSceneTables* tables) {             \
    PnPlanarFrame##S frame;                                                                                \
    frame.n = face.plane.xyz;                                                                              \
    frame.h = planar_height##S(px, py, pz, lx, ly, lz, face, tables);                                      \
    frame.nn = nx * frame.n.x + ny * frame.n.y + nz * frame.n.z;                                           \
    frame.dpsi_sum = 0.0f;                                                                                 \
    return frame;                                                                                          \
  }                                                                                                        \
  /* N·(Q − P) for a vertex Q of the scene's tables at x, y, z = Q − P (pn_from): N·(Q − V0) − h \
   * from the double-float positions where that rounds less than N·(x, y, z), whose rounding is up        \
   * to u (|N_x x| + |N_y y| + |N_z z|) against u (|N·(Q − V0)| + h). The image of Q on the plane,      \
   * (Q − P) h / −N·(Q − P), moves by its distance from P over sin e times the relative rounding    \
   * of N·(Q − P): for a tilted face and an occluder near its plane (a bezel) that is r/sin e from      \
   * P's distance, and only the bezel's own height from the heights. A face along the scene's axes         \
   * (planar_heights_kept false) needs none: N·(x, y, z) is one coordinate, rounded to u of               \
   * itself, and |N·(Q − P)| <= |N·(Q − V0)| + h. */                                                 \
  inline T planar_depth##S(PnPosition q, T x, T y, T z, PnSourceFace face,                                 \
                           const PnPlanarFrame##S* frame, const PnSceneTables* tables) {                   \
    const float3 n = face.plane.xyz;                                                                       \
    const T np = n.x * x + n.y * y + n.z * z;                                                              \
    const float hq = planar_height1(q.hi.x, q.hi.y, q.hi.z, q.lo.x, q.lo.y, q.lo.z, face, tables);         \
    const T spread = fabs(n.x * x) + fabs(n.y * y) + fabs(n.z * z);                                        \
    return select(np, hq - frame->h, fabs(hq) + fabs(frame->h) < spread);                                  \
  }

/* The term of the edge a → b (vectors from P, both in the face's plane): 2 Σ_k c_k M_k(edge)
 * less its Δψ part, which *dpsi receives (the caller sums them for planar_closing##S). */
#define PN_DEFINE_PLANAR_TERM(T, M, S, Sum, add)                                                            \
  inline T planar_term##S(T ax, T ay, T az, T bx, T by, T bz, const PnPlanarFrame##S* frame, T nx,          \
                          T ny, T nz, const PnEmission* em, T* dpsi) {                                      \
    const T h = frame->h, nn = frame->nn;                                                                   \
    const float3 N = frame->n;                                                                              \
    /* The edge in the plane: F + A, F + B, t its direction, m = t × N, d = m·A, ta and tb the            \
     * positions of A and B along t from the foot of the perpendicular from F; d and the positions          \
     * from the edge's midpoint, so that the edge b → a gives exactly −(its term) (a contour that       \
     * runs along an edge and back, as the horizon's chord of a face that only touches the horizon          \
     * does, sums to 0). */                                                                                 \
    const T fx = 0.5f * (ax + bx) + h * N.x, fy = 0.5f * (ay + by) + h * N.y,                               \
            fz = 0.5f * (az + bz) + h * N.z;                                                                \
    /* b − a, less its part along N where that is more than PN_PLANAR_ALONG_N of it: an edge              \
     * seen end-on (an occluder's edge taken to the plane, both ends on one ray) is then as short           \
     * along t as it is in the plane, not the ends' heights' rounding long along N. Below, the              \
     * part is that rounding, and taking it out would only round b − a again. */                          \
    const T e0x = bx - ax, e0y = by - ay, e0z = bz - az;                                                    \
    const T en = e0x * N.x + e0y * N.y + e0z * N.z;                                                         \
    const M along_n = fabs(en) > PN_PLANAR_ALONG_N * sqrt(e0x * e0x + e0y * e0y + e0z * e0z);               \
    const T ex = select(e0x, e0x - en * N.x, along_n), ey = select(e0y, e0y - en * N.y, along_n),           \
            ez = select(e0z, e0z - en * N.z, along_n);                                                      \
    const T len = sqrt(ex * ex + ey * ey + ez * ez);                                                        \
    const M degenerate = len <= 0.0f;                                                                       \
    const T inv = 1.0f / select(len, (T)(1.0f), degenerate);                                                \
    const T tx = ex * inv, ty = ey * inv, tz = ez * inv;                                                    \
    const T mx = ty * N.z - tz * N.y, my = tz * N.x - tx * N.z, mz = tx * N.y - ty * N.x;                   \
    const T d = mx * fx + my * fy + mz * fz;                                                                \
    const T mid = tx * fx + ty * fy + tz * fz, ta = mid - 0.5f * len, tb = mid + 0.5f * len;                \
    const T d2 = d * d, h2 = h * h, big_d2 = d2 + h2, big_d = sqrt(big_d2);                                 \
    const T theta = atan2(len * big_d, big_d2 + ta * tb);                                                   \
    const T psi = atan2(d * len, d2 + ta * tb);                                                             \
    *dpsi = select(psi, (T)(0.0f), degenerate);                                                             \
    const T q = h2 / big_d2; /* (h / D)², the largest g² on the edge's line */                            \
    const M tail = q <= PN_PLANAR_TAIL_RATIO;                                                               \
    const T nm = nx * mx + ny * my + nz * mz;                                                               \
    const T d_over_h = d / fmax(h, 1e-30f);                                                                 \
    const T j2 = h * theta / big_d;                                                                         \
    T term;                                                                                                 \
    if (em->order <= 0 || em->order > PN_MOMENT_DIRECT_ORDER) {                                             \
      /* Uniform luminance (and a narrow beam's c_0): A_2 = Δψ − (d/h) J_2 = Δψ − c θ sgn d,       \
       * c = |d| / D. Where h²/D² is small, as sgn d (atan(u) − c atan(c u)) between the ends           \
       * (u = τ/|d|), written without cancellation: atan of the difference of atan(u) − atan(c u)        \
       * at both ends, plus (1 − c) θ, 1 − c = h² / (D (D + |d|)). */                                 \
      const T ad = fabs(d), omc = h2 / (big_d * (big_d + ad)), c = 1.0f - omc;                              \
      const T num = omc * ad * len * (d2 - c * ta * tb);                                                    \
      const T den = (d2 + c * ta * ta) * (d2 + c * tb * tb) + omc * omc * d2 * ta * tb;                     \
      const T a2_tail = copysign(atan2(num, den) + omc * theta, d);                                         \
      const T a2 = select(psi - d_over_h * j2, a2_tail, tail);                                              \
      const float c0 = em->order < 0 ? 1.0f : em->c[0];                                                     \
      term = -c0 * (nm * j2 - nn * a2);                                                                     \
      if (em->order > PN_MOMENT_DIRECT_ORDER) {                                                             \
        /* A narrow beam's powers above 0 (luminance_moments.cl's azimuth form) by the moment term          \
         * with their Δψ part left to the closing (its azimuth about w = −N is Δψ about F). Where     \
         * the moment term keeps its direct recurrences (an arc near the axis), their Δψ part is          \
         * taken out here instead. */                                                                       \
        const T cx = ey * az - ez * ay, cy = ez * ax - ex * az, cz = ex * ay - ey * ax;                     \
        const T s = sqrt(cx * cx + cy * cy + cz * cz);                                                      \
        const PnArcShares##S none = {0.0f, 0.0f, 0.0f};                                                     \
        M azimuth = 0;                                                                                      \
        const T high = moment_term##S(ax, ay, az, bx, by, bz, cx, cy, cz, s, nx, ny, nz, &none,             \
                                      em, &azimuth);                                                        \
        const float beyond =                                                                                \
            em->tail[em->order] + em->tail[em->order - 1]; /* Σ_{k>=1} c_k/(k+2) */                        \
        const T high_rest = select(high + 2.0f * nn * psi * beyond, high, azimuth);                         \
        term += select(high_rest, (T)(0.0f), s <= 0.0f);                                                    \
      }                                                                                                     \
    } else {                                                                                                \
      /* J_p, p = 2 .. last (the tail's powers where some lane takes it). */                                \
      const int order = em->order;                                                                          \
      const int last = pn_any(tail) ? order + 2 + 2 * PN_PLANAR_TAIL : order + 2;                           \
      const T ra = sqrt(ta * ta + big_d2), rb = sqrt(tb * tb + big_d2);                                     \
      const T ga = h / ra, gb = h / rb, ua = ta / ra, ub = tb / rb;                                         \
      /* ub − ua without cancellation where both ends lie on one side of the perpendicular's foot:        \
       * (tb² ra² − ta² rb²) / (…) = len (ta + tb) D² / ((tb ra + ta rb) ra rb). */                \
      const T du = select(ub - ua, len * (ta + tb) * big_d2 / ((tb * ra + ta * rb) * ra * rb),              \
                          ta * tb > 0.0f);                                                                  \
      T j[PN_PLANAR_MAX_P + 1];                                                                             \
      j[2] = j2;                                                                                            \
      j[3] = q * du;                                                                                        \
      /* The bracket [u g^{p−1}]_A^B as du g_B^{p−1} + u_A (g_B^{p−1} − g_A^{p−1}), the latter by \
       * D_{n+1} = g_B D_n + g_A^n (g_B − g_A), g_B − g_A = −h len (ta + tb) / (ra rb (ra + rb)):     \
       * each a product of small factors where the edge is short against its distance. */                   \
      const T dg = -h * len * (ta + tb) / (ra * rb * (ra + rb));                                            \
      T pa = ga, pb = gb, dp = dg; /* g^{p−1} at both ends, and their difference */                       \
      for (int p = 2; p + 2 <= last; ++p) {                                                                 \
        const float pf = (float)p;                                                                          \
        j[p + 2] = q * ((du * pb + ua * dp) / pf + (pf - 1.0f) / pf * j[p]);                                \
        dp = gb * dp + pa * dg;                                                                             \
        pa *= ga;                                                                                           \
        pb *= gb;                                                                                           \
      }                                                                                                     \
      /* A_p forward from A_0 = Δψ and A_1 = [atan(h τ / (d r))]_A^B, in the lanes not in the            \
       * tail; the tail lanes' A_p = (d/h) Σ_{j>=1} J_{p+2j}, from the highest p down. */                  \
      T a_even = psi, a_odd = atan2(h * d * du, d2 + h2 * ua * ub);                                         \
      Sum inplane = {0.0f, 0.0f}, normal = {0.0f, 0.0f};                                                    \
      for (int k = 0; k <= order; ++k) {                                                                    \
        const int p = k + 2;                                                                                \
        const float ck = em->c[k] / (float)p;                                                               \
        T* a = (p & 1) ? &a_odd : &a_even;                                                                  \
        *a -= d_over_h * j[p];                                                                              \
        add(&inplane, j[p] * ck);                                                                           \
        add(&normal, select(*a, (T)(0.0f), tail) * ck);                                                     \
      }                                                                                                     \
      if (pn_any(tail)) {                                                                                   \
        T tail_even = 0.0f, tail_odd = 0.0f;                                                                \
        for (int p = last; p >= order + 3; --p) {                                                           \
          if (p & 1)                                                                                        \
            tail_odd += j[p];                                                                               \
          else                                                                                              \
            tail_even += j[p];                                                                              \
        }                                                                                                   \
        for (int k = order; k >= 0; --k) {                                                                  \
          const int p = k + 2;                                                                              \
          T* sum = (p & 1) ? &tail_odd : &tail_even;                                                        \
          add(&normal, em->c[k] / (float)p * select((T)(0.0f), d_over_h * *sum, tail));                     \
          *sum += j[p];                                                                                     \
        }                                                                                                   \
      }                                                                                                     \
      term = -2.0f * (nm * (inplane.s + inplane.c) - nn * (normal.s + normal.c));                           \
    }                                                                                                       \
    return select(term, (T)(0.0f), degenerate);                                                             \
  }

/* The face's Δψ part: −2 (n·N) Σ_k c_k / (k + 2) times the sum of its edges' Δψ, which is 2π
 * times the winding of the contour about F, 0 or 2π up to the terms' rounding, and is taken as
 * that. Where F lies on the contour (within PN_PLANAR_ON_CONTOUR rad of the sum) the sum is the
 * angle the region spans at F (π on an edge, the corner's angle at a vertex) and is kept as it
 * is: E is then of the order of the face-on light, and nothing cancels. */
#define PN_PLANAR_ON_CONTOUR 1e-3f
#define PN_DEFINE_PLANAR_CLOSING(T, M, S)                                                          \
  inline T planar_closing##S(const PnPlanarFrame##S* frame, const PnEmission* em) {                \
    const T dpsi_sum = frame->dpsi_sum, nn = frame->nn;                                            \
    const float two_pi = 6.283185307f;                                                             \
    T winding = rint(dpsi_sum / two_pi) * two_pi;                                                  \
    winding = select(dpsi_sum, winding, fabs(dpsi_sum - winding) < PN_PLANAR_ON_CONTOUR);          \
    float weight = 0.0f;                                                                           \
    const int order = em->order < 0 ? 0 : em->order;                                               \
    for (int k = 0; k <= order; ++k) weight += (em->order < 0 ? 1.0f : em->c[k]) / (float)(k + 2); \
    return -2.0f * nn * winding * weight;                                                          \
  }

#define PN_DEFINE_PLANAR_TWINS(T, M, S, Sum, add) \
  PN_DEFINE_PLANAR_FRAME(T, M, S, Sum, add)       \
  PN_DEFINE_PLANAR_TERM(T, M, S, Sum, add)        \
  PN_DEFINE_PLANAR_CLOSING(T, M, S)
PN_DEFINE_PLANAR_TWINS(float, int, 1, PnSum, pn_sum_add)     /* one body for the scalar path */
PN_DEFINE_PLANAR_TWINS(float8, int8, 8, PnSum8, pn_sum_add8) /* and for eight lanes */
#undef PN_DEFINE_PLANAR_TWINS
#undef PN_DEFINE_PLANAR_FRAME
#undef PN_DEFINE_PLANAR_TERM
#undef PN_DEFINE_PLANAR_CLOSING

/* The planar frame of a face for the work-item's lanes. */
inline PnPlanarFrame8 planar_frame8(const Points8* pts, PnSourceFace face,
                                    const PnSceneTables* tables) {
  return planar_frame_at8(pts->px, pts->py, pts->pz, pts->lx, pts->ly, pts->lz, pts->nx, pts->ny,
                          pts->nz, face, tables);
}
