#pragma once
// Which occluders can shade a receiver (Nishita §2.4, step v): those whose penumbra volume meets
// it. A sample then tests only those. The receiver is a face (a convex polygon, as the paper
// has it) or the bounding box of a patch of sample points (what the kernel's work-items are: a
// floor as large as an open office would otherwise list every occluder for every sample).
#include <span>
#include <vector>

#include "geometry/bounding_box.hpp"
#include "shadow/scene_shadows.hpp"

namespace penumbra {

// Indices into face.casters whose penumbra volume, grown by `margin` (m), meets the polygon.
std::vector<int> candidatesForFace(const EmittingFaceShadows& face, const ConvexPolygon& receiver,
                                   double margin);

// The casters among `among` (indices into face.casters) whose grown penumbra volume may meet the
// box: none of its planes has the whole box outside. Conservative: near a volume's edges a box
// may be kept that misses it.
std::vector<int> candidatesForBox(const EmittingFaceShadows& face, const BoundingBox& box,
                                  std::span<const int> among, double margin);

}  // namespace penumbra
