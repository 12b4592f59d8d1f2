#pragma once
// The scene as the illuminance kernel reads it: flat arrays of the structs in
// kernels/shared_types.h. Built once on the host in double precision, stored as float.
#include <span>
#include <string>
#include <vector>

#include "cl/buffer.hpp"
#include "geometry/sample_point.hpp"
#include "geometry/tolerance.hpp"
#include "kernels/shared_types.h"
#include "shadow/scene_shadows.hpp"

namespace penumbra {

struct KernelScene {
  // Every position the kernel reads is relative to this point, the centre of the bounding box of
  // the scene's geometry (Scene::geometryBounds: solids, sources, luminaires; not the grids, so
  // that where a grid lies moves nothing the kernel resolves) (points too: IlluminanceEngine
  // subtracts it before rounding them to float). Points and the vertices of sources and
  // occluders, which the kernel subtracts from each other, come as double-float pairs
  // (PnPosition, toPosition); planes as floats.
  // Float spacing grows with magnitude: in a 12 × 8 m office, coordinates from the room's corner
  // reach 12 m, where floats are 9.5e-7 m apart; from the centre they reach 6 m (4.8e-7 m), and
  // most lie within 4 m (2.4e-7 m). A point 2 cm from a thin solid sees that solid's shadow
  // edge on a panel 2 m away move a hundred times as far as the rounding moves either of them.
  Vec3 origin = Vec3::Zero();
  std::vector<PnSourceFace> faces;
  std::vector<PnAperture> apertures;  // PnSourceFace::aperture indexes these
  std::vector<PnPosition> sourceVertices;
  std::vector<PnLuminancePolynomial> luminances;  // PnSourceFace::luminance indexes these
  std::vector<PnOccluder> occluders;              // per face, its casters in SceneShadows order
  // Occluder face planes, separating planes, penumbra planes, umbra planes.
  std::vector<cl_float4> planes;
  std::vector<cl_int4> edges;  // (from, to, left, right), local to their occluder
  std::vector<PnPosition> occluderVertices;
  // The kernel's length tolerance near the origin (m, Tolerance::kernelLength(0)); at a point it
  // grows with the point's distance from the origin (kernelLengthAt).
  float epsLength = 0.0f;
  int sourceCount = 0;
};

// x − origin as the kernel reads a position it subtracts from another: hi = float(x − origin),
// lo = float(x − origin − hi) (kernels/shared_types.h, PnPosition).
PnPosition toPosition(const Vec3& x, const Vec3& origin);

// The kernel's copy of `shadows`, with the luminance of each face from `scene`, relative to the
// centre of scene.bounds(). Throws std::runtime_error when a face or solid exceeds the kernel's
// limits (shared_types.h).
KernelScene packScene(const Scene& scene, const SceneShadows& shadows);
// packScene in steps: the frame (origin, tolerance, source count), then each face in order.
KernelScene packSceneFrame(const Scene& scene);
void packFace(KernelScene& packed, const Scene& scene, const EmittingFaceShadows& emitting,
              const Tolerance& tolerance);

// The largest length tolerance (m) the kernel uses at any of `points` (Tolerance::kernelLength of
// their largest coordinate relative to packed.origin): what host tests that the kernel repeats in
// float must allow for.
double kernelLengthAt(const KernelScene& packed, std::span<const SamplePoint> points);

// The build options of the illuminance program (kernels/illuminance.cl): OpenCL C 1.2 and the
// kernel's tolerances, Tolerance::kKernelRelative and Tolerance::kKernelLengthRelative.
std::string illuminanceBuildOptions();

// The buffers of the kernel `illuminance`, one field per __global argument, in its order. Points
// are structure-of-arrays, padded to whole work-items, their positions in hi and lo parts
// (toPosition); the scene's tables come from a KernelScene, the patch table from
// buildPatchTable; the last three are written.
struct IlluminanceBuffers {
  const compute::DeviceBuffer* pointX = nullptr;
  const compute::DeviceBuffer* pointY = nullptr;
  const compute::DeviceBuffer* pointZ = nullptr;
  const compute::DeviceBuffer* pointXLo = nullptr;
  const compute::DeviceBuffer* pointYLo = nullptr;
  const compute::DeviceBuffer* pointZLo = nullptr;
  const compute::DeviceBuffer* normalX = nullptr;
  const compute::DeviceBuffer* normalY = nullptr;
  const compute::DeviceBuffer* normalZ = nullptr;
  const compute::DeviceBuffer* pointSolid = nullptr;
  const compute::DeviceBuffer* faces = nullptr;
  const compute::DeviceBuffer* sourceVertices = nullptr;
  const compute::DeviceBuffer* luminances = nullptr;
  const compute::DeviceBuffer* occluders = nullptr;
  const compute::DeviceBuffer* planes = nullptr;
  const compute::DeviceBuffer* edges = nullptr;
  const compute::DeviceBuffer* occluderVertices = nullptr;
  const compute::DeviceBuffer* apertures = nullptr;
  const compute::DeviceBuffer* patchFaces = nullptr;
  const compute::DeviceBuffer* candidates = nullptr;
  // With PnLaunchParams::linked: work-item g's links are [linkStart[g], linkStart[g + 1]) of
  // linkFaces (source face indices); otherwise any buffer (the kernel does not read them).
  const compute::DeviceBuffer* linkStart = nullptr;
  const compute::DeviceBuffer* linkFaces = nullptr;
  const compute::DeviceBuffer* illuminance =
      nullptr;                                     // lx: per point, [source][point] or [link][lane]
  const compute::DeviceBuffer* errors = nullptr;   // PN_ERROR_* bits per work-item
  const compute::DeviceBuffer* classes = nullptr;  // ShadowClass, [source][point]
};

// The kernel's argument names as kernels/illuminance.cl spells them, in the order
// bindIlluminanceArguments binds them: "params" (a PnLaunchParams by value), then one per
// IlluminanceBuffers field.
std::vector<std::string> illuminanceArgumentNames();

// Binds every argument of the kernel `illuminance`. Throws std::logic_error for a missing buffer.
void bindIlluminanceArguments(compute::KernelLaunch& launch, const PnLaunchParams& params,
                              const IlluminanceBuffers& buffers);

}  // namespace penumbra
