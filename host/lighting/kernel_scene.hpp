#pragma once
// The scene as the illuminance kernel reads it: flat arrays of the structs in
// kernels/shared_types.h. Built once on the host in double precision, stored as float.
#include <vector>

#include "geometry/tolerance.hpp"
#include "kernels/shared_types.h"
#include "scene/scene.hpp"

namespace penumbra {

struct KernelScene {
  std::vector<PnSourceFace> faces;
  std::vector<cl_float4> sourceVertices;
  std::vector<PnOccluder> occluders;
  std::vector<cl_float4> planes;  // occluder face planes, then each occluder's separating planes
  std::vector<cl_int4> edges;     // (from, to, left, right), local to their occluder
  std::vector<cl_float4> occluderVertices;
  float epsLength = 0.0f;  // absolute length tolerance the kernel uses (m)
};

// Every source face, with every solid clipped to that face's front half-space (Nishita: "the
// portion of the positive-space of S_e"); solids left with no volume are dropped. Throws
// std::runtime_error when a face or solid exceeds the kernel's limits (shared_types.h).
KernelScene packScene(const Scene& scene);

}  // namespace penumbra
