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

// Derivative of `values` along one axis at pixel i from the neighbours before and after it that lie
// in its region: central where both do, one-sided where one does, 0 where neither.
float regionDerivative(const std::vector<float>& values, const RegionMap& regions, size_t i,
                       bool hasBefore, size_t before, bool hasAfter, size_t after) {
  const int32_t r = regions.region[i];
  const bool b = hasBefore && regions.region[before] == r;
  const bool a = hasAfter && regions.region[after] == r;
  if (a && b) return 0.5f * (values[after] - values[before]);
  if (a) return values[after] - values[i];
  if (b) return values[i] - values[before];
  return 0;
}

// |∇ log V₀| per pixel, from neighbours in the pixel's own region only (an edge is no gradient).
std::vector<float> regionGradientMagnitude(const std::vector<float>& values,
                                           const RegionMap& regions) {
  const int width = regions.width, height = regions.height;
  std::vector<float> magnitude(values.size(), 0.0f);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = regions.index(x, y);
      if (regions.region[i] == RegionMap::kNone) continue;
      const float gx = regionDerivative(values, regions, i, x > 0, i - 1, x + 1 < width, i + 1);
      const float gy =
          regionDerivative(values, regions, i, y > 0, i - width, y + 1 < height, i + width);
      magnitude[i] = std::hypot(gx, gy);
    }
  }
  return magnitude;
}

}  // namespace

double LogScene::edgeTarget(double d) const {
  const double shown = std::abs(d) <= kEdgeKnee ? d : softPower(d, kEdgeKnee, kEdgeExponent);
  return std::clamp(shown, -kEdgeCap, kEdgeCap);
}

double LogScene::insideTarget(double d, double distance, size_t a, size_t b) const {
  // The log gradient's magnitude there: the pixels' own, or the pair's mean slope where that is
  // larger (a shadow edge between the two vertices).
  const double gradient =
      std::max(0.5 * (gradientMagnitude[a] + gradientMagnitude[b]), std::abs(d) / distance);
  if (gradient <= 0) return 0;
  return d * std::pow(gradient / kInsideKnee, kInsideExponent - 1);
}

double LogScene::exposedValue(size_t pixel) const {
  return exposedLogValue(logValue[pixel]);
}

double LogScene::exposedLogValue(double value) const {
  const double y = std::exp(value - logWhite);
  const double lowerBound = std::exp(logLowerBound);
  return std::log(lowerBound + (1 - lowerBound) * y / (1 + y));
}

double LogScene::levelEdgeTarget(double d) const {
  const double shown =
      std::pow(kLevelEdgeKnee, 1 - kLevelExponent) * std::pow(std::abs(d), kLevelExponent);
  return std::copysign(std::min(shown, kLevelEdgeCap), d);
}

double LogScene::levelInsideFactor(double gradient) const {
  return std::pow(gradient / kLevelKnee, kLevelExponent - 1);
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
  scene.gradientMagnitude = regionGradientMagnitude(scene.logValue, regions);
  return scene;
}

}  // namespace penumbra
