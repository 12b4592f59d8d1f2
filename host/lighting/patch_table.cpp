#include "lighting/patch_table.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "shadow/face_class.hpp"
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

// `emission` is the face's plane, computed once per face (ConvexPolygon::plane() is a Newell sum).
FaceClass patchClass(std::span<const SamplePoint> points, std::size_t first,
                     const EmittingFaceShadows& face, const Plane& emission) {
  bool allC = true, allA = true;
  for (std::size_t i = first; i < first + PN_LANES; ++i) {
    const SamplePoint& p = pointAt(points, i);
    const FaceClass c = classifyPoint(p.position, p.normal, face.face.vertices(), emission);
    allC = allC && c == FaceClass::C;
    allA = allA && c == FaceClass::A;
  }
  return allC ? FaceClass::C : allA ? FaceClass::A : FaceClass::B;
}

int kernelClass(FaceClass c) {
  switch (c) {
    case FaceClass::A:
      return PN_CLASS_A;
    case FaceClass::B:
      return PN_CLASS_B;
    case FaceClass::C:
      return PN_CLASS_C;
  }
  return PN_CLASS_B;
}

}  // namespace

PatchTable buildPatchTable(const SceneShadows& shadows, const KernelScene& packed,
                           std::span<const SamplePoint> points, std::size_t workItems, bool culling,
                           double margin) {
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
  tbb::parallel_for(std::size_t{0}, supers * faceCount, [&](std::size_t sf) {
    const std::size_t firstItem = sf / faceCount * kGroupsPerSuper * kItemsPerGroup;
    const std::size_t items = std::min(kGroupsPerSuper * kItemsPerGroup, workItems - firstItem);
    const EmittingFaceShadows& face = shadows.faces[sf % faceCount];
    std::vector<int> all(face.casters.size());
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
    superCandidates[sf] =
        candidatesForBox(face, boxOf(points, firstItem * PN_LANES, items * PN_LANES), all, margin);
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
    for (std::size_t f = 0; f < faceCount; ++f) {
      const EmittingFaceShadows& face = shadows.faces[f];
      const std::vector<int> near = candidatesForBox(
          face, groupBox, superCandidates[g / kGroupsPerSuper * faceCount + f], margin);
      for (std::size_t w = firstItem; w < firstItem + items; ++w) {
        PnPatchFace& entry = table.entries[w * faceCount + f];
        const FaceClass c = patchClass(points, w * PN_LANES, face, emission[f]);
        entry = PnPatchFace{static_cast<cl_int>(list.size()), 0, kernelClass(c), 0};
        if (c == FaceClass::C || near.empty()) continue;
        for (int k : candidatesForBox(face, itemBoxes[w - firstItem], near, margin))
          list.push_back(packed.faces[f].firstOccluder + k);
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
