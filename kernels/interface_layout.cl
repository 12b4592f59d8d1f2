/* The layout of the structs that cross host and device, as the kernel compiler lays them out,
 * for tests/launch_interface_test.cpp to compare with the host's: out[0] the count of values
 * that follow; then PnLaunchParams' size and its fields' offsets, the other shared structs'
 * sizes, and the fields of the PnLaunchParams this kernel was passed by value (the float as its
 * bits). Add a field here and in the test together. */

#include "shared_types.h"

__kernel void interface_layout(const PnLaunchParams params, __global int* out) {
  int n = 1;
  out[n++] = (int)sizeof(PnLaunchParams);
  out[n++] = (int)__builtin_offsetof(PnLaunchParams, faceCount);
  out[n++] = (int)__builtin_offsetof(PnLaunchParams, epsLength);
  out[n++] = (int)__builtin_offsetof(PnLaunchParams, paths);
  out[n++] = (int)__builtin_offsetof(PnLaunchParams, bySource);
  out[n++] = (int)__builtin_offsetof(PnLaunchParams, sourceStride);
  out[n++] = (int)__builtin_offsetof(PnLaunchParams, linked);
  out[n++] = (int)sizeof(PnSourceFace);
  out[n++] = (int)sizeof(PnAperture);
  out[n++] = (int)sizeof(PnOccluder);
  out[n++] = (int)sizeof(PnPatchFace);
  out[n++] = (int)sizeof(PnVisibleObject);
  out[n++] = (int)sizeof(PnLuminancePolynomial);
  out[n++] = (int)__builtin_offsetof(PnLuminancePolynomial, coefficient);
  out[n++] = (int)__builtin_offsetof(PnLuminancePolynomial, order);
  out[n++] = (int)sizeof(PnPosition);
  out[n++] = (int)__builtin_offsetof(PnPosition, lo);
  out[n++] = params.faceCount;
  out[n++] = as_int(params.epsLength);
  out[n++] = params.paths;
  out[n++] = params.bySource;
  out[n++] = params.sourceStride;
  out[n++] = params.linked;
  out[0] = n - 1;
}
