#include "engine/facet_error.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra {

FacetError facetError(IlluminanceEngine& engine, const ConvexPolyhedron& facets, const Vec3& centre,
                      const std::vector<SamplePoint>& onSmooth, double floor) {
  std::vector<SamplePoint> onFacets;
  for (const SamplePoint& p : onSmooth) {
    // The ray from the centre through p leaves the polyhedron through the face whose plane it
    // meets first (the centre is inside every plane).
    const Vec3 d = p.position - centre;
    double tBest = INFINITY;
    Vec3 normal = Vec3::UnitZ();
    for (const ConvexPolyhedron::Face& face : facets.faces()) {
      const double denom = face.plane.normal.dot(d);
      if (denom <= 0.0) continue;
      const double t = -face.plane.signedDistance(centre) / denom;
      if (t < tBest) {
        tBest = t;
        normal = face.plane.normal;
      }
    }
    onFacets.push_back(SamplePoint{centre + tBest * d, normal, -1});
  }
  const std::vector<double> smooth = engine.illuminance(onSmooth);
  const std::vector<double> faceted = engine.illuminance(onFacets);
  const double largest = *std::max_element(smooth.begin(), smooth.end());
  FacetError error;
  for (std::size_t i = 0; i < smooth.size(); ++i) {
    if (smooth[i] < floor * largest) continue;
    const double relative = std::abs(faceted[i] - smooth[i]) / smooth[i];
    error.mean += relative;
    error.max = std::max(error.max, relative);
    ++error.points;
  }
  if (error.points > 0) error.mean /= error.points;
  return error;
}

}  // namespace penumbra
