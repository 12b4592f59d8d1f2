#include "engine/patch_table.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

#include "memory/page_prefault.hpp"
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

// The solid that every one of `count` points from `first` lies on, or -1 (none, or not one).
int commonSolid(std::span<const SamplePoint> points, std::size_t first, std::size_t count) {
  const int solid = pointAt(points, first).solid;
  for (std::size_t i = first + 1; i < first + count; ++i)
    if (pointAt(points, i).solid != solid) return -1;
  return solid;
}

// Drops from `near` the casters whose solid is `common`, the one every point of a group lies on:
// the kernel never lets a solid shade its own points, so such a caster shades none of them (a
// floor slab under a work plane's points, a desk under its top's).
void dropOwnSolid(const FaceVolumes& volumes, int common, std::vector<int>& near) {
  if (common >= 0) std::erase_if(near, [&](int k) { return volumes.solid[k] == common; });
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

// What the entry of a patch and a face reads of the face.
struct FaceOfPatch {
  const EmittingFaceShadows& face;
  const FaceVolumes& volumes;
  const Plane& emission;
  cl_int firstOccluder;  // the face's first occluder in KernelScene::occluders
};

// The entry of work-item w (whose points' box is `box`) for a face: class C when no point faces
// it; else class Umbra when one caster hides it from the whole box (`hiddenAround`: one hides it
// from a box holding this one); else class B with the casters among `near` (those that may meet
// a box holding this one) whose volume meets `box`, appended to `list`. `found` is scratch.
PnPatchFace patchEntry(const FaceOfPatch& of, std::span<const SamplePoint> points, std::size_t w,
                       const BoundingBox& box, std::span<const int> near, bool hiddenAround,
                       double margin, std::vector<int>& found, std::vector<cl_int>& list) {
  const bool dark = patchSeesNothing(points, w * PN_LANES, of.face, of.emission);
  PnPatchFace entry{static_cast<cl_int>(list.size()), 0, dark ? PN_CLASS_C : PN_CLASS_B, 0};
  if (dark) return entry;
  if (!hiddenAround && near.empty()) return entry;  // no caster near: the unoccluded face
  bool hidden = hiddenAround;
  if (!hidden) {
    boxCandidates(of.volumes, box, near, margin, found);
    hidden = boxHidden(of.volumes, box, found, margin, points, w * PN_LANES, PN_LANES);
  }
  if (hidden) {
    entry.faceClass = PN_CLASS_UMBRA;
    entry.facingLanes = facingLanes(points, w, of.face, of.emission);
    return entry;
  }
  for (int k : found) list.push_back(of.firstOccluder + k);
  entry.candidateCount = static_cast<cl_int>(list.size()) - entry.firstCandidate;
  return entry;
}

}  // namespace

std::vector<FaceVolumes> flattenVolumes(const SceneShadows& shadows) {
  std::vector<FaceVolumes> all;
  for (const EmittingFaceShadows& face : shadows.faces) all.push_back(flattenVolumes(face));
  return all;
}

FaceVolumes flattenVolumes(const EmittingFaceShadows& face) {
  FaceVolumes v;
  v.first.push_back(0);
  v.umbraFirst.push_back(0);
  for (const ShadowCaster& caster : face.casters) {
    v.planes.insert(v.planes.end(), caster.volume.penumbra.begin(), caster.volume.penumbra.end());
    v.first.push_back(v.planes.size());
    if (!caster.behindAperture)
      v.umbraPlanes.insert(v.umbraPlanes.end(), caster.volume.umbra.begin(),
                           caster.volume.umbra.end());
    v.umbraFirst.push_back(v.umbraPlanes.size());
    v.solid.push_back(caster.solid);
    BoundingBox box;
    for (const Vec3& vertex : caster.shape.vertices()) box.add(vertex);
    v.box.push_back(box);
  }
  return v;
}

namespace {

// The emitting faces grouped by the caster face whose volumes they read
// (EmittingFaceShadows::casterFace): the elements of one caster block share its casters, so for
// a box the candidates and the umbra test are the same for every face of a group and are found
// once. Groups in the order of their first face, faces in increasing order.
struct CasterGroups {
  std::vector<std::size_t> volumesOf;             // group → its caster face
  std::vector<std::vector<std::size_t>> members;  // group → its emitting faces
};

CasterGroups casterGroups(const SceneShadows& shadows) {
  CasterGroups groups;
  std::vector<int> groupOf(shadows.faces.size(), -1);  // caster face → group
  for (std::size_t f = 0; f < shadows.faces.size(); ++f) {
    if (!shadows.faces[f].emits) continue;
    const std::size_t c = shadows.faces[f].casterFace(f);
    if (groupOf[c] < 0) {
      groupOf[c] = static_cast<int>(groups.members.size());
      groups.volumesOf.push_back(c);
      groups.members.emplace_back();
    }
    groups.members[static_cast<std::size_t>(groupOf[c])].push_back(f);
  }
  return groups;
}

}  // namespace

PatchTable buildPatchTable(const SceneShadows& shadows, std::span<const FaceVolumes> volumes,
                           const KernelScene& packed, std::span<const SamplePoint> points,
                           std::size_t workItems, bool culling, double margin,
                           std::span<const char> skipFace) {
  const std::size_t faceCount = shadows.faces.size();
  const auto skip = [skipFace](std::size_t f) { return !skipFace.empty() && skipFace[f] != 0; };
  PatchTable table;
  resizePopulated(table.entries, workItems * faceCount);
  if (!culling) {
    for (std::size_t k = 0; k < table.entries.size(); ++k)
      table.entries[k] = PnPatchFace{
          0, -1,
          shadows.faces[k % faceCount].emits && !skip(k % faceCount) ? PN_CLASS_B : PN_CLASS_C, 0};
    return table;
  }
  const CasterGroups casters = casterGroups(shadows);
  const std::size_t casterCount = casters.members.size();
  // Caster groups whose faces are all skipped: no search.
  std::vector<char> groupSkipped(casterCount);
  for (std::size_t c = 0; c < casterCount; ++c)
    groupSkipped[c] = std::all_of(casters.members[c].begin(), casters.members[c].end(), skip);
  const auto skipped = [&](std::size_t c) { return groupSkipped[c] != 0; };
  // Each group fills its own entries and a private candidate list; the lists are joined in
  // group order afterwards, so the table does not depend on the thread count.
  const std::size_t groups = (workItems + kItemsPerGroup - 1) / kItemsPerGroup;
  const std::size_t supers = (groups + kGroupsPerSuper - 1) / kGroupsPerSuper;
  // [super * casterCount + c]: the casters of caster group c that may meet the super-group's box,
  // and whether one of them hides the group's faces from all of it.
  std::vector<std::vector<int>> superCandidates(supers * casterCount);
  std::vector<char> superHidden(supers * casterCount);
  // Each super-group's box once, not once per face: with element faces as sources (thousands)
  // the boxes would cost as much as the table.
  std::vector<BoundingBox> superBoxes(supers);
  tbb::parallel_for(std::size_t{0}, supers, [&](std::size_t super) {
    const std::size_t firstItem = super * kGroupsPerSuper * kItemsPerGroup;
    const std::size_t items = std::min(kGroupsPerSuper * kItemsPerGroup, workItems - firstItem);
    superBoxes[super] = boxOf(points, firstItem * PN_LANES, items * PN_LANES);
  });
  tbb::parallel_for(std::size_t{0}, supers * casterCount, [&](std::size_t sc) {
    const std::size_t firstItem = sc / casterCount * kGroupsPerSuper * kItemsPerGroup;
    const std::size_t items = std::min(kGroupsPerSuper * kItemsPerGroup, workItems - firstItem);
    if (skipped(sc % casterCount)) return;
    const FaceVolumes& faceVolumes = volumes[casters.volumesOf[sc % casterCount]];
    std::vector<int> all(faceVolumes.solid.size());
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<int>(k);
    const BoundingBox& box = superBoxes[sc / casterCount];
    boxCandidates(faceVolumes, box, all, margin, superCandidates[sc]);
    superHidden[sc] = boxHidden(faceVolumes, box, superCandidates[sc], margin, points,
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
    // Faces that emit nothing (Source::castersOnly) and those skipped: class C.
    for (std::size_t f = 0; f < faceCount; ++f)
      if (!shadows.faces[f].emits || skip(f))
        for (std::size_t w = firstItem; w < firstItem + items; ++w)
          table.entries[w * faceCount + f] = PnPatchFace{0, 0, PN_CLASS_C, 0};
    std::vector<int> near, found;
    const int groupSolid = commonSolid(points, firstItem * PN_LANES, items * PN_LANES);
    for (std::size_t c = 0; c < casterCount; ++c) {
      if (skipped(c)) continue;
      const FaceVolumes& faceVolumes = volumes[casters.volumesOf[c]];
      // A caster that hides the faces from a whole super-group or group (a wall between them
      // and another room's light) hides them from each of its work-items.
      const std::size_t sc = g / kGroupsPerSuper * casterCount + c;
      bool groupHidden = superHidden[sc];
      near.clear();
      if (!groupHidden) {
        boxCandidates(faceVolumes, groupBox, superCandidates[sc], margin, near);
        groupHidden = boxHidden(faceVolumes, groupBox, near, margin, points, firstItem * PN_LANES,
                                items * PN_LANES);
        dropOwnSolid(faceVolumes, groupSolid, near);
      }
      for (std::size_t w = firstItem; w < firstItem + items; ++w) {
        // The work-item's candidates and umbra test, searched at its first face that some
        // lane faces, and shared by the group's faces (one candidate list for all of them).
        bool searched = false, hidden = groupHidden;
        cl_int first = 0, count = 0;
        for (std::size_t f : casters.members[c]) {
          const EmittingFaceShadows& face = shadows.faces[f];
          PnPatchFace& entry = table.entries[w * faceCount + f];
          if (skip(f)) continue;  // class C above
          if (patchSeesNothing(points, w * PN_LANES, face, emission[f])) {
            entry = PnPatchFace{0, 0, PN_CLASS_C, 0};
            continue;
          }
          if (!searched) {
            searched = true;
            if (!hidden && !near.empty()) {
              boxCandidates(faceVolumes, itemBoxes[w - firstItem], near, margin, found);
              hidden = boxHidden(faceVolumes, itemBoxes[w - firstItem], found, margin, points,
                                 w * PN_LANES, PN_LANES);
              if (!hidden) {
                first = static_cast<cl_int>(list.size());
                for (int k : found) list.push_back(packed.faces[f].firstOccluder + k);
                count = static_cast<cl_int>(list.size()) - first;
              }
            }
          }
          entry = hidden
                      ? PnPatchFace{0, 0, PN_CLASS_UMBRA, facingLanes(points, w, face, emission[f])}
                      : PnPatchFace{first, count, PN_CLASS_B, 0};
        }
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

namespace penumbra {

PatchTable buildLinkPatchTable(const SceneShadows& shadows, std::span<const FaceVolumes> volumes,
                               const KernelScene& packed, std::span<const SamplePoint> points,
                               const FaceLinks& links, bool culling, double margin) {
  const std::size_t workItems = links.start.size() - 1;
  PatchTable table;
  resizePopulated(table.entries, links.faces.size());
  if (!culling) {
    for (PnPatchFace& e : table.entries) e = PnPatchFace{0, -1, PN_CLASS_B, 0};
    return table;
  }
  // Work-items in groups as buildPatchTable's, each group's candidates in a list of its own,
  // joined in group order: the table does not depend on the thread count.
  const std::size_t groups = (workItems + kItemsPerGroup - 1) / kItemsPerGroup;
  std::vector<std::vector<cl_int>> groupCandidates(groups);
  tbb::parallel_for(std::size_t{0}, groups, [&](std::size_t g) {
    std::vector<int> near, found;
    const std::size_t end = std::min(workItems, (g + 1) * kItemsPerGroup);
    // Runs of work-items of one receiver (the same faces): the casters near each face are
    // searched once for the run's box, then among those per work-item.
    for (std::size_t first = g * kItemsPerGroup; first < end;) {
      std::size_t last = first + 1;
      while (last < end && !links.receiver.empty() && links.receiver[last] == links.receiver[first])
        ++last;
      const BoundingBox runBox = boxOf(points, first * PN_LANES, (last - first) * PN_LANES);
      std::vector<BoundingBox> itemBoxes;
      for (std::size_t w = first; w < last; ++w)
        itemBoxes.push_back(boxOf(points, w * PN_LANES, PN_LANES));
      const cl_int count = links.start[first + 1] - links.start[first];
      for (cl_int j = 0; j < count; ++j) {
        const auto f = static_cast<std::size_t>(links.faces[links.start[first] + j]);
        const EmittingFaceShadows& face = shadows.faces[f];
        const FaceVolumes& faceVolumes = volumes[face.casterFace(f)];
        BoundingBox shaft = runBox;
        for (const Vec3& v : face.face.vertices()) shaft.add(v);
        shaft = shaft.grown(margin);
        near.clear();
        for (std::size_t c = 0; c < faceVolumes.box.size(); ++c)
          if (faceVolumes.box[c].overlaps(shaft)) near.push_back(static_cast<int>(c));
        const Plane emission = face.face.plane();
        const FaceOfPatch of{face, faceVolumes, emission, packed.faces[f].firstOccluder};
        for (std::size_t w = first; w < last; ++w)
          table.entries[links.start[w] + j] = patchEntry(of, points, w, itemBoxes[w - first], near,
                                                         false, margin, found, groupCandidates[g]);
      }
      first = last;
    }
  });
  std::size_t offset = 0;
  for (std::size_t g = 0; g < groups; ++g) {
    const std::size_t end = std::min(workItems, (g + 1) * kItemsPerGroup);
    for (cl_int k = links.start[g * kItemsPerGroup]; k < links.start[end]; ++k)
      table.entries[k].firstCandidate += static_cast<cl_int>(offset);
    offset += groupCandidates[g].size();
    table.candidates.insert(table.candidates.end(), groupCandidates[g].begin(),
                            groupCandidates[g].end());
  }
  return table;
}

}  // namespace penumbra
