#include "tonemap/log_scene.hpp"

#include <algorithm>
#include <cmath>

#include "tonemap/baseline_maps.hpp"

namespace penumbra {
namespace {

// Below this share of MaxRGB a V₀ counts as this share: an umbra (V₀ = 0 in a direct-light
// render) gets a finite log, 9.2 below the brightest, past any display's range.
constexpr double kLogFloor = 1e-4;

// k·(|d|/k)^exponent with the sign of d.
double softPower(double d, double knee, double exponent) {
  const double size = std::abs(d);
  if (size <= 0) return 0;
  return std::copysign(knee * std::pow(size / knee, exponent), d);
}

}  // namespace

double LogScene::edgeTarget(double d) const {
  const double shown = std::abs(d) <= kEdgeKnee ? d : softPower(d, kEdgeKnee, kEdgeExponent);
  return std::clamp(shown, -kEdgeCap, kEdgeCap);
}

double LogScene::insideTarget(double d, double distance) const {
  return softPower(d, kInsideKnee * distance, kInsideExponent);
}

double LogScene::exposedValue(size_t pixel) const {
  const double y = std::exp(static_cast<double>(logValue[pixel]) - logWhite);
  const double lowerBound = std::exp(logLowerBound);
  return std::log(lowerBound + (1 - lowerBound) * y / (1 + y));
}

LogScene logScene(const DisplaySpaces& spaces, const RegionMap& regions) {
  LogScene scene;
  scene.logLowerBound = std::log(spaces.lowerBound);
  // The clip map's automatic exposure: the surfaces' log average at y = 0.18.
  scene.logWhite = std::log(automaticWhite(spaces, regions));
  const double floor = std::max(spaces.maxRgb, 1e-30) * kLogFloor;
  scene.logValue.resize(spaces.value0.size());
  for (size_t i = 0; i < spaces.value0.size(); ++i) {
    scene.logValue[i] = static_cast<float>(std::log(std::max<double>(spaces.value0[i], floor)));
  }
  return scene;
}

}  // namespace penumbra
