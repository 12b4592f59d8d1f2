#pragma once
// The scene as the illuminance kernel reads it: flat arrays of the structs in
// kernels/shared_types.h. Built once on the host in double precision, stored as float.
#include <vector>

#include "geometry/tolerance.hpp"
#include "kernels/shared_types.h"
#include "shadow/scene_shadows.hpp"

namespace penumbra {

struct KernelScene {
  // Every position the kernel reads is relative to this point, the centre of the scene's
  // bounding box (points too: IlluminanceEngine subtracts it before rounding them to float).
  // Float spacing grows with magnitude: in a 12 × 8 m office, coordinates from the room's corner
  // reach 12 m, where floats are 9.5e-7 m apart; from the centre they reach 6 m (4.8e-7 m), and
  // most lie within 4 m (2.4e-7 m). A point 2 cm from a thin solid sees that solid's shadow
  // edge on a panel 2 m away move a hundred times as far as the rounding moves either of them.
  Vec3 origin = Vec3::Zero();
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

// The kernel's copy of `shadows`, with the luminance of each face from `scene`, relative to the
// centre of scene.bounds(). Throws std::runtime_error when a face or solid exceeds the kernel's
// limits (shared_types.h).
KernelScene packScene(const Scene& scene, const SceneShadows& shadows);

}  // namespace penumbra
