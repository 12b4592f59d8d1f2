#pragma once
// Per work-item of the illuminance kernel (a patch of PN_LANES consecutive points) and per
// source face: the patch's face class and its candidate occluders (Nishita §2.2 steps iii and
// v, on patches of samples rather than whole faces). Built on the host for every batch of points.
#include <span>
#include <vector>

#include "engine/kernel_scene.hpp"
#include "geometry/bounding_box.hpp"
#include "geometry/sample_point.hpp"
#include "kernels/shared_types.h"
#include "shadow/scene_shadows.hpp"

namespace penumbra {

struct PatchTable {
  std::vector<PnPatchFace> entries;  // [workItem * faceCount + face]
  std::vector<cl_int> candidates;    // indices into KernelScene::occluders
};

// Every face's casters' penumbra planes in one array per face (built once per scene): the box
// tests read them for every patch, and the casters themselves are large objects scattered in
// memory (the tests waited on cache misses).
struct FaceVolumes {
  std::vector<Plane> planes;
  std::vector<std::size_t> first;  // caster k: planes [first[k], first[k + 1])
  // Caster k's umbra planes [umbraFirst[k], umbraFirst[k + 1]), none when it claims no umbra or
  // is behind the face's aperture (the kernel skips it for points that see the face through it).
  std::vector<Plane> umbraPlanes;
  std::vector<std::size_t> umbraFirst;
  std::vector<int> solid;        // caster k's solid: it does not shade points on that solid
  std::vector<BoundingBox> box;  // caster k's clipped solid's bounding box
};
std::vector<FaceVolumes> flattenVolumes(const SceneShadows& shadows);
FaceVolumes flattenVolumes(const EmittingFaceShadows& face);

// `points` padded as the kernel sees them: work-item w holds points [w·PN_LANES, (w+1)·PN_LANES)
// and the padding repeats the last point. `margin` (m) grows every penumbra volume and shrinks
// every umbra volume, to cover the kernel's own tolerance and float rounding. A patch that lies
// inside one caster's shrunk umbra gets class PN_CLASS_UMBRA: the kernel's own umbra test would
// give every lane 0 (the volumes are in host/shadow/shadow_volume.hpp), and skipping the face
// keeps a room's cost from growing with the lights of the rooms beyond its walls. With culling
// off every entry lists all occluders of its face with class B: the plain path.
// `volumes` is flattenVolumes(shadows). Faces f with skipFace[f] set (when skipFace is not
// empty) get class PN_CLASS_C without a search: the kernel gives them E = 0 (a caller that needs
// only the other faces' values).
PatchTable buildPatchTable(const SceneShadows& shadows, std::span<const FaceVolumes> volumes,
                           const KernelScene& packed, std::span<const SamplePoint> points,
                           std::size_t workItems, bool culling, double margin,
                           std::span<const char> skipFace = {});

// Links: work-item w of a linked launch takes the source faces faces[k] for k in
// [start[w], start[w + 1]) (start has one entry more than there are work-items).
struct FaceLinks {
  std::span<const cl_int> start;
  std::span<const cl_int> faces;
  // Optional, per work-item: consecutive work-items with the same value have the same faces in
  // the same order (the points of one receiving element); empty: each its own.
  std::span<const cl_int> receiver = {};
};

// The patch table of a linked launch: entry k for link k (its work-item's points and its face),
// by the same tests as buildPatchTable's, each link's casters searched among those of its face
// whose box meets the box around the work-item's points and the face (a caster outside it meets
// no segment between them, so it shades none of them).
PatchTable buildLinkPatchTable(const SceneShadows& shadows, std::span<const FaceVolumes> volumes,
                               const KernelScene& packed, std::span<const SamplePoint> points,
                               const FaceLinks& links, bool culling, double margin);

}  // namespace penumbra
