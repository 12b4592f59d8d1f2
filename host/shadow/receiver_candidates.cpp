#include "shadow/receiver_candidates.hpp"

namespace penumbra {

std::vector<int> candidatesForFace(const EmittingFaceShadows& face, const ConvexPolygon& receiver,
                                   double margin) {
  std::vector<int> found;
  for (int k = 0; k < static_cast<int>(face.casters.size()); ++k) {
    ConvexPolygon part = receiver;
    for (const Plane& plane : face.casters[k].volume.penumbra) {
      part = part.clipped(Plane{plane.normal, plane.offset + margin}, 0.0);
      if (part.empty()) break;
    }
    if (!part.empty()) found.push_back(k);
  }
  return found;
}

std::vector<int> candidatesForBox(const EmittingFaceShadows& face, const BoundingBox& box,
                                  std::span<const int> among, double margin) {
  const Vec3 centre = 0.5 * (box.lo + box.hi);
  const Vec3 half = 0.5 * (box.hi - box.lo);
  std::vector<int> found;
  for (int k : among) {
    bool meets = true;
    for (const Plane& plane : face.casters[k].volume.penumbra) {
      // The box corner deepest inside the half-space.
      const double nearest = plane.signedDistance(centre) - plane.normal.cwiseAbs().dot(half);
      if (nearest > margin) {
        meets = false;
        break;
      }
    }
    if (meets) found.push_back(k);
  }
  return found;
}

}  // namespace penumbra
