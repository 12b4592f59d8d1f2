#include "engine/patch_table.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "shadow/receiver_candidates.hpp"

namespace penumbra {

namespace {

// Work-items are grouped by 16, and groups by 8, for coarse passes over a face's casters: the
// casters whose volume meets a super-group's box (1 024 points), then among those the ones that
// meet a group's box, then a work-item's. A caster that meets a box meets every box holding it,
// so each list is the same as a search of all casters would give.
constexpr std::size_t kItemsPerGroup = 16;
constexpr std::size_t kGroupsPerSuper = 8;

const SamplePoint& pointAt(std::span<const SamplePoint> points, std::size_t i) {
  return points[std::min(i, points.size() - 1)];
}

BoundingBox boxOf(std::span<const SamplePoint> points, std::size_t first, std::size_t count) {
  BoundingBox box;
  for (std::size_t i = first; i < first + count; ++i) box.add(pointAt(points, i).position);
  return box;
}

// Whether a point may receive light from the face, i.e. is not of class C (shadow/face_class.hpp:
// not strictly in front of the face's plane `emission`, or every vertex on or below its horizon).
bool facesTheFace(const SamplePoint& p, const EmittingFaceShadows& face, const Plane& emission) {
  if (emission.signedDistance(p.position) <= 0.0) return false;
  for (const Vec3& q : face.face.vertices())
    if (p.normal.dot(q - p.position) > 0.0) return true;
  return false;
}

// Whether no point of the patch receives anything from the face: every point is of class C.
// The first point that sees a vertex answers, so this is about one test per patch. Whether the
// horizon cuts the face (class A or B) the kernel finds for itself.
bool patchSeesNothing(std::span<const SamplePoint> points, std::size_t first,
                      const EmittingFaceShadows& face, const Plane& emission) {
  for (std::size_t i = first; i < first + PN_LANES; ++i)
    if (facesTheFace(pointAt(points, i), face, emission)) return false;
  return true;
}

// candidatesForBox (shadow/receiver_candidates.hpp) on the flattened volumes, the same
// arithmetic: the casters among `among` whose grown penumbra volume may meet the box, into
// `found` (cleared first).
void boxCandidates(const FaceVolumes& volumes, const BoundingBox& box, std::span<const int> among,
                   double margin, std::vector<int>& found) {
  const Vec3 centre = 0.5 * (box.lo + box.hi);
  const Vec3 half = 0.5 * (box.hi - box.lo);
  found.clear();
  for (int k : among) {
    bool meets = true;
    for (std::size_t j = volumes.first[k]; j < volumes.first[k + 1] && meets; ++j) {
      const Plane& plane = volumes.planes[j];
      // The box corner deepest inside the half-space.
      meets = !(plane.signedDistance(centre) - plane.normal.cwiseAbs().dot(half) > margin);
    }
    if (meets) found.push_back(k);
  }
}

// Whether one of the casters `among` hides the face from every point of the box: the box lies
// deeper than `margin` inside the caster's umbra (each plane's box corner least inside it), and
// none of `points` lies on the caster's solid (the kernel does not let a solid shade its own
// points).
bool boxHidden(const FaceVolumes& volumes, const BoundingBox& box, std::span<const int> among,
               double margin, std::span<const SamplePoint> points, std::size_t first,
               std::size_t count) {
  const Vec3 centre = 0.5 * (box.lo + box.hi);
  const Vec3 half = 0.5 * (box.hi - box.lo);
  for (int k : among) {
    const std::size_t begin = volumes.umbraFirst[k], end = volumes.umbraFirst[k + 1];
    if (begin == end) continue;
    bool inside = true;
    for (std::size_t j = begin; j < end && inside; ++j) {
      const Plane& plane = volumes.umbraPlanes[j];
      inside = plane.signedDistance(centre) + plane.normal.cwiseAbs().dot(half) < -margin;
    }
    for (std::size_t i = first; i < first + count && inside; ++i)
      inside = pointAt(points, i).solid != volumes.solid[k];
    if (inside) return true;
  }
  return false;
}

// The lanes of work-item w that face the source's face (facesTheFace): in an umbra, the kernel's
// shadow class Umbra rather than Unlit.
cl_int facingLanes(std::span<const SamplePoint> points, std::size_t w,
                   const EmittingFaceShadows& face, const Plane& emission) {
  cl_int lanes = 0;
  for (std::size_t l = 0; l < PN_LANES; ++l)
    if (facesTheFace(pointAt(points, w * PN_LANES + l), face, emission)) lanes |= cl_int{1} << l;
  return lanes;
}

}  // namespace

std::vector<FaceVolumes> flattenVolumes(const SceneShadows& shadows) {
  std::vector<FaceVolumes> all(shadows.faces.size());
  for (std::size_t f = 0; f < all.size(); ++f) {
    FaceVolumes& v = all[f];
    v.first.push_back(0);
    v.umbraFirst.push_back(0);
    for (const ShadowCaster& caster : shadows.faces[f].casters) {
      v.planes.insert(v.planes.end(), caster.volume.penumbra.begin(), caster.volume.penumbra.end());
      v.first.push_back(v.planes.size());
      if (!caster.behindAperture)
        v.umbraPlanes.insert(v.umbraPlanes.end(), caster.volume.umbra.begin(),
                             caster.volume.umbra.end());
      v.umbraFirst.push_back(v.umbraPlanes.size());
      v.solid.push_back(caster.solid);
    }
  }
  return all;
}

PatchTable buildPatchTable(const SceneShadows& shadows, std::span<const FaceVolumes> volumes,
                           const KernelScene& packed, std::span<const SamplePoint> points,
                           std::size_t workItems, bool culling, double margin) {
  const std::size_t faceCount = shadows.faces.size();
  PatchTable table;
  table.entries.resize(workItems * faceCount);
  if (!culling) {
    for (PnPatchFace& e : table.entries) e = PnPatchFace{0, -1, PN_CLASS_B, 0};
    return table;
  }
  // Each group fills its own entries and a private candidate list; the lists are joined in
  // group order afterwards, so the table does not depend on the thread count.
  const std::size_t groups = (workItems + kItemsPerGroup - 1) / kItemsPerGroup;
  const std::size_t supers = (groups + kGroupsPerSuper - 1) / kGroupsPerSuper;
  std::vector<std::vector<int>> superCandidates(supers * faceCount);  // [super * faceCount + f]
  std::vector<char> superHidden(supers * faceCount);  // one caster hides f from the super-group
  tbb::parallel_for(std::size_t{0}, supers * faceCount, [&](std::size_t sf) {
    const std::size_t firstItem = sf / faceCount * kGroupsPerSuper * kItemsPerGroup;
    const std::size_t items = std::min(kGroupsPerSuper * kItemsPerGroup, workItems - firstItem);
    const std::size_t f = sf % faceCount;
    std::vector<int> all(shadows.faces[f].casters.size());
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
    const BoundingBox box = boxOf(points, firstItem * PN_LANES, items * PN_LANES);
    boxCandidates(volumes[f], box, all, margin, superCandidates[sf]);
    superHidden[sf] = boxHidden(volumes[f], box, superCandidates[sf], margin, points,
                                firstItem * PN_LANES, items * PN_LANES);
  });
  std::vector<Plane> emission(faceCount);
  for (std::size_t f = 0; f < faceCount; ++f) emission[f] = shadows.faces[f].face.plane();
  std::vector<std::vector<cl_int>> groupCandidates(groups);
  tbb::parallel_for(std::size_t{0}, groups, [&](std::size_t g) {
    const std::size_t firstItem = g * kItemsPerGroup;
    const std::size_t items = std::min(kItemsPerGroup, workItems - firstItem);
    const BoundingBox groupBox = boxOf(points, firstItem * PN_LANES, items * PN_LANES);
    std::vector<cl_int>& list = groupCandidates[g];
    std::vector<BoundingBox> itemBoxes(items);
    for (std::size_t w = 0; w < items; ++w)
      itemBoxes[w] = boxOf(points, (firstItem + w) * PN_LANES, PN_LANES);
    std::vector<int> near, found;
    for (std::size_t f = 0; f < faceCount; ++f) {
      const EmittingFaceShadows& face = shadows.faces[f];
      // A caster that hides the face from a whole super-group or group (a wall between it and
      // another room's light) hides it from each of its work-items.
      const std::size_t sf = g / kGroupsPerSuper * faceCount + f;
      bool groupHidden = superHidden[sf];
      if (!groupHidden) {
        boxCandidates(volumes[f], groupBox, superCandidates[sf], margin, near);
        groupHidden = boxHidden(volumes[f], groupBox, near, margin, points, firstItem * PN_LANES,
                                items * PN_LANES);
      }
      for (std::size_t w = firstItem; w < firstItem + items; ++w) {
        PnPatchFace& entry = table.entries[w * faceCount + f];
        const bool dark = patchSeesNothing(points, w * PN_LANES, face, emission[f]);
        entry = PnPatchFace{static_cast<cl_int>(list.size()), 0, dark ? PN_CLASS_C : PN_CLASS_B, 0};
        if (dark) continue;
        if (!groupHidden && near.empty()) continue;  // no caster near: the unoccluded face
        bool hidden = groupHidden;
        if (!hidden) {
          boxCandidates(volumes[f], itemBoxes[w - firstItem], near, margin, found);
          hidden = boxHidden(volumes[f], itemBoxes[w - firstItem], found, margin, points,
                             w * PN_LANES, PN_LANES);
        }
        if (hidden) {
          entry.faceClass = PN_CLASS_UMBRA;
          entry.facingLanes = facingLanes(points, w, face, emission[f]);
          continue;
        }
        for (int k : found) list.push_back(packed.faces[f].firstOccluder + k);
        entry.candidateCount = static_cast<cl_int>(list.size()) - entry.firstCandidate;
      }
    }
  });
  std::size_t offset = 0;
  for (std::size_t g = 0; g < groups; ++g) {
    const std::size_t firstItem = g * kItemsPerGroup;
    const std::size_t items = std::min(kItemsPerGroup, workItems - firstItem);
    for (std::size_t w = firstItem; w < firstItem + items; ++w)
      for (std::size_t f = 0; f < faceCount; ++f)
        table.entries[w * faceCount + f].firstCandidate += static_cast<cl_int>(offset);
    offset += groupCandidates[g].size();
    table.candidates.insert(table.candidates.end(), groupCandidates[g].begin(),
                            groupCandidates[g].end());
  }
  return table;
}

}  // namespace penumbra
