/* Shared by every file of the illuminance kernel: the tolerances the host passes, the lane-mask
 * test and the compensated sums.
 *
 * Build options from the host: -DPN_EPS_REL=<Tolerance::kKernelRelative>,
 * -DPN_EPS_LENGTH_REL=<Tolerance::kKernelLengthRelative>. */

#include "shared_types.h"

/* The scene's tables and the batch's patch table, gathered by the entry from its arguments (one
 * __global argument each: a kernel argument may not be a struct holding pointers) and passed to
 * the functions that read them. */
typedef struct {
  __global const PnSourceFace* faces;
  __global const PnPosition* sourceVertices;
  __global const PnLuminancePolynomial* luminances; /* PnSourceFace::luminance indexes these */
  __global const PnOccluder* occluders;
  __global const float4* planes; /* occluder faces, separating, penumbra and umbra planes */
  __global const int4* edges;    /* per occluder: (from, to, left face, right face) */
  __global const PnPosition* occluderVertices;
  __global const PnAperture* apertures;
  __global const PnPatchFace* patchFaces; /* [work-item][face] */
  __global const int* candidates;         /* occluder indices, listed by PnPatchFace */
} PnSceneTables;

#ifndef PN_EPS_REL
#error "the host passes -DPN_EPS_REL"
#endif
#ifndef PN_EPS_LENGTH_REL
#error "the host passes -DPN_EPS_LENGTH_REL"
#endif

/* The length tolerance at a point (m; Tolerance::kernelLength): plane heights there are good to a
 * few roundings of the point's largest coordinate r (positions are relative to the scene's
 * centre), so the tolerance is PN_EPS_LENGTH_REL · r, and `near` (the host's epsLength, its value
 * within 1 m of the centre) where that is less. A point, not the scene, sets it: a 10 mm shelf
 * 50 m from the centre is 200 tolerances thick there, whatever the scene's size. */
#define PN_DEFINE_LENGTH_TOLERANCE(T, S)                                                  \
  inline T length_tolerance##S(float near, T px, T py, T pz) {                            \
    return fmax((T)(near), PN_EPS_LENGTH_REL * fmax(fabs(px), fmax(fabs(py), fabs(pz)))); \
  }
PN_DEFINE_LENGTH_TOLERANCE(float, 1)
PN_DEFINE_LENGTH_TOLERANCE(float8, 8)
#undef PN_DEFINE_LENGTH_TOLERANCE

/* Whether any lane of a mask is set: a comparison's result for one point (int: 0 or 1) or for
 * eight lanes (int8: 0 or -1 each), so that code written once for both types can test it. PoCL's
 * any() extracts the eight lanes one by one; a vector OR-reduction compiles to one vptest. */
inline bool __attribute__((overloadable)) pn_any(int m) {
  return m != 0;
}
inline bool __attribute__((overloadable)) pn_any(int8 m) {
  return __builtin_reduce_or(m) != 0;
}
/* Whether every lane of a mask is set (one point: whether it is). */
inline bool __attribute__((overloadable)) pn_all(int m) {
  return m != 0;
}
inline bool __attribute__((overloadable)) pn_all(int8 m) {
  return __builtin_reduce_and(m) != 0;
}

/* Compensated sums (Knuth's TwoSum: s + c carries the sum to about twice float precision). A
 * contour's terms are large and cancel: a window 7 m away past a column gives terms of 0.29 that
 * sum to 0.015, and each rounding of a running sum of such terms is as large as the rest of the
 * error. TwoSum, not Kahan, because a term may be larger than the sum so far. Safe as written:
 * OpenCL C reassociates nothing unless built with -cl-unsafe-math-optimizations (the host does
 * not), and there is no product here to contract into an fma. Every sum of terms and of faces
 * uses it, for about 1.6 % more kernel instructions: the rounding of the sums is then well below
 * the 1e-6 of E_unoccluded that culling_test holds the default and plain paths to. */
#define PN_DEFINE_SUM(T, Sum, add)        \
  typedef struct {                        \
    T s, c;                               \
  } Sum;                                  \
  inline void add(Sum* a, T x) {          \
    T t = a->s + x, bp = t - a->s;        \
    a->c += (a->s - (t - bp)) + (x - bp); \
    a->s = t;                             \
  }
PN_DEFINE_SUM(float, PnSum, pn_sum_add)    /* one body for the scalar path */
PN_DEFINE_SUM(float8, PnSum8, pn_sum_add8) /* and for eight lanes */
#undef PN_DEFINE_SUM

/* The height of a point above a plane (xyz its unit normal, w its offset), positive on the side
 * the normal points to, and the front test of a source face: only points strictly in front of a
 * face see it. Written once for one point (T float, names ending in 1) and eight lanes (float8,
 * 8), M the mask type: where both paths test a plane they read the same bits. */
#define PN_DEFINE_PLANE_TESTS(T, M, S)                        \
  inline T plane_height##S(float4 pl, T px, T py, T pz) {     \
    return pl.x * px + pl.y * py + pl.z * pz - pl.w;          \
  }                                                           \
  inline M in_front##S(PnSourceFace face, T px, T py, T pz) { \
    return plane_height##S(face.plane, px, py, pz) > 0.0f;    \
  }
PN_DEFINE_PLANE_TESTS(float, int, 1)
PN_DEFINE_PLANE_TESTS(float8, int8, 8)
#undef PN_DEFINE_PLANE_TESTS

/* The work-item's eight points: positions (hi parts in px, py, pz, what plane tests read; lo
 * parts in lx, ly, lz: PnPosition), unit normals and the solid each lies on. */
typedef struct {
  float8 px, py, pz, lx, ly, lz, nx, ny, nz;
  int8 own;
} Points8;

/* q − P for a position q of the scene's tables and a point P, both double-float (PnPosition):
 * (q.hi − P.hi) + (q.lo − P.lo), per coordinate. The first difference is exact where q and P are
 * within a factor 2 of each other, so the result is good to one rounding of itself however far
 * from the origin both lie. Written for one point and, per coordinate, for eight lanes (the same
 * operations, so both paths read the same bits). */
inline float3 pn_from1(PnPosition q, float3 p, float3 p_lo) {
  return (q.hi.xyz - p) + (q.lo.xyz - p_lo);
}
inline void pn_from8(PnPosition q, const Points8* pts, float8* x, float8* y, float8* z) {
  *x = (q.hi.x - pts->px) + (q.lo.x - pts->lx);
  *y = (q.hi.y - pts->py) + (q.lo.y - pts->ly);
  *z = (q.hi.z - pts->pz) + (q.lo.z - pts->lz);
}

/* a·b written out as the eight-lane code writes its dot products (contracted into fma the same
 * way; dot() rounds differently), for the scalar tests that must read what the lane tests read. */
inline float pn_dot(float3 a, float3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
