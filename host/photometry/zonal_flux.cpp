#include "photometry/zonal_flux.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "geometry/angles.hpp"

namespace penumbra::photometry {
namespace {

// The zone edges of each node: midpoints to the neighbours, the end nodes' own angles outside.
std::vector<double> zoneEdges(const std::vector<double>& nodes) {
  std::vector<double> edges{nodes.front()};
  for (std::size_t i = 1; i < nodes.size(); ++i) edges.push_back((nodes[i - 1] + nodes[i]) / 2);
  edges.push_back(nodes.back());
  return edges;
}

// The width (rad) of each plane's share of the circle (periodic) or of the measured range.
std::vector<double> planeWidths(const std::vector<double>& planes, bool periodic) {
  const std::size_t n = planes.size();
  std::vector<double> widths(n);
  if (periodic) {
    for (std::size_t j = 0; j < n; ++j) {
      const double before = j == 0 ? planes[n - 1] - 360 : planes[j - 1];
      const double after = j + 1 == n ? planes[0] + 360 : planes[j + 1];
      widths[j] = n == 1 ? 2 * std::numbers::pi : (after - before) / 2 * kRadiansPerDegree;
    }
    return widths;
  }
  const std::vector<double> edges = zoneEdges(planes);
  for (std::size_t j = 0; j < n; ++j) widths[j] = (edges[j + 1] - edges[j]) * kRadiansPerDegree;
  return widths;
}

}  // namespace

double zonalFlux(const LightDistribution& distribution) {
  const std::vector<double>& planes = distribution.planeAnglesDeg();
  const std::vector<double>& inPlane = distribution.inPlaneAnglesDeg();
  const std::vector<double> widths = planeWidths(planes, distribution.periodicPlanes());
  const std::vector<double> edges = zoneEdges(inPlane);
  const bool polar = distribution.type() == PhotometricType::C;
  double flux = 0;
  for (std::size_t k = 0; k < inPlane.size(); ++k) {
    // sr per radian of plane: type C's γ is a polar angle, A's and B's in-plane angle a latitude.
    const double zone =
        polar ? std::cos(edges[k] * kRadiansPerDegree) - std::cos(edges[k + 1] * kRadiansPerDegree)
              : std::sin(edges[k + 1] * kRadiansPerDegree) - std::sin(edges[k] * kRadiansPerDegree);
    double ring = 0;
    for (std::size_t j = 0; j < planes.size(); ++j) ring += distribution.candela(j, k) * widths[j];
    flux += ring * zone;
  }
  return flux;
}

FluxComparison compareFlux(const PhotometricData& data, const LightDistribution& distribution) {
  FluxComparison comparison;
  comparison.zonalLm = zonalFlux(distribution);
  if (data.lightOutputRatio && data.lampLumens > 0) {
    comparison.fileLm = data.lampLumens * *data.lightOutputRatio;
    if (*comparison.fileLm > 0) {
      comparison.relativeDifference =
          (comparison.zonalLm - *comparison.fileLm) / *comparison.fileLm;
    }
  }
  return comparison;
}

}  // namespace penumbra::photometry
