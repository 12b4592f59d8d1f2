#pragma once
// The scene as the illuminance kernel reads it: flat arrays of the structs in
// kernels/shared_types.h. Built once on the host in double precision, stored as float.
#include <vector>

#include "geometry/tolerance.hpp"
#include "kernels/shared_types.h"
#include "shadow/scene_shadows.hpp"

namespace penumbra {

struct KernelScene {
  std::vector<PnSourceFace> faces;
  std::vector<PnAperture> apertures;  // PnSourceFace::aperture indexes these
  std::vector<cl_float4> sourceVertices;
  std::vector<PnOccluder> occluders;  // per face, its casters in SceneShadows order
  // Occluder face planes, separating planes, penumbra planes, umbra planes.
  std::vector<cl_float4> planes;
  std::vector<cl_int4> edges;  // (from, to, left, right), local to their occluder
  std::vector<cl_float4> occluderVertices;
  float epsLength = 0.0f;  // absolute length tolerance the kernel uses (m)
  int sourceCount = 0;
};

// The kernel's copy of `shadows`, with the luminance of each face from `scene`. Throws
// std::runtime_error when a face or solid exceeds the kernel's limits (shared_types.h).
KernelScene packScene(const Scene& scene, const SceneShadows& shadows);

}  // namespace penumbra
