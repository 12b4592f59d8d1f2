/* Shared by every file of the illuminance kernel: the tolerance the host passes, the lane-mask
 * test and the compensated sums.
 *
 * Build options from the host: -DPN_EPS_REL=<Tolerance::kKernelRelative>. */

#include "shared_types.h"

/* The scene's tables and the batch's patch table, gathered by the entry from its arguments (one
 * __global argument each: a kernel argument may not be a struct holding pointers) and passed to
 * the functions that read them. */
typedef struct {
  __global const PnSourceFace* faces;
  __global const float4* sourceVertices;
  __global const PnOccluder* occluders;
  __global const float4* planes; /* occluder faces, separating, penumbra and umbra planes */
  __global const int4* edges;    /* per occluder: (from, to, left face, right face) */
  __global const float4* occluderVertices;
  __global const PnAperture* apertures;
  __global const PnPatchFace* patchFaces; /* [work-item][face] */
  __global const int* candidates;         /* occluder indices, listed by PnPatchFace */
} PnSceneTables;

#ifndef PN_EPS_REL
#error "the host passes -DPN_EPS_REL"
#endif

/* Whether any lane of a mask (lanes all ones or all zeros, as comparisons give) is set. PoCL's
 * any() extracts the eight lanes one by one; a vector OR-reduction compiles to one vptest. */
inline bool pn_any(int8 m) {
  return __builtin_reduce_or(m) != 0;
}

/* Compensated sums (Knuth's TwoSum: s + c carries the sum to about twice float precision). A
 * contour's terms are large and cancel: a window 7 m away past a column gives terms of 0.29 that
 * sum to 0.015, and each rounding of a running sum of such terms is as large as the rest of the
 * error. TwoSum, not Kahan, because a term may be larger than the sum so far. Safe as written:
 * OpenCL C reassociates nothing unless built with -cl-unsafe-math-optimizations (the host does
 * not), and there is no product here to contract into an fma. Every sum of terms and of faces
 * uses it (culling_test: the default and plain paths went from 1.25e-6 to 8.8e-7 of
 * E_unoccluded apart on the open office, for 1.6 % more kernel instructions). */
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
