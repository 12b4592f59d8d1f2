#include "tonemap/halo.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <vector>

#include "tonemap/region_map.hpp"

namespace penumbra {
namespace {

// Scene values across a 4-neighbour pair differ by at least `ratio` (a dark side at 0 counts).
bool strongPair(double a, double b, double ratio) {
  const double low = std::min(a, b), high = std::max(a, b);
  return high > 0 && high >= ratio * low;
}

struct RegionSums {
  std::vector<double> nearRatio;  // per distance 0 … band-1: Σ display / predicted
  std::vector<int> nearCount;
  // Far pixels: sums for the least-squares line log display = a + b log scene.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  double lowest = HUGE_VAL, highest = -HUGE_VAL;  // log scene range of the far pixels
  int farCount = 0;
  double a = 0, b = 1;
};

// Below this spread of log scene values (a flat region) the far pixels fix no slope: b = 1, a
// pure gain.
constexpr double kFlatLogSpread = 0.05;
// A display value within 5 % of the image's darkest counts as held at black.
constexpr double kFloorMargin = 0.05;

constexpr int kUnreached = -1;

// Per pixel: 4-steps inside its region from the nearest pixel of the region that has a
// 4-neighbour in another region across a strong edge (breadth first); kUnreached when none.
std::vector<int> distanceFromStrongEdges(const RegionMap& regions, const ScalarImage& sceneValue,
                                         double edgeRatio) {
  const int width = regions.width, height = regions.height;
  std::vector<int> distance(regions.region.size(), kUnreached);
  std::deque<size_t> queue;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = regions.index(x, y);
      const int32_t r = regions.region[i];
      if (r == RegionMap::kNone) continue;
      bool seed = false;
      const auto check = [&](int nx, int ny) {
        const size_t n = regions.index(nx, ny);
        if (regions.region[n] != r && regions.region[n] != RegionMap::kNone &&
            strongPair(sceneValue.values[i], sceneValue.values[n], edgeRatio)) {
          seed = true;
        }
      };
      if (x > 0) check(x - 1, y);
      if (x + 1 < width) check(x + 1, y);
      if (y > 0) check(x, y - 1);
      if (y + 1 < height) check(x, y + 1);
      if (seed) distance[i] = 0, queue.push_back(i);
    }
  }
  while (!queue.empty()) {
    const size_t i = queue.front();
    queue.pop_front();
    const int x = static_cast<int>(i % width), y = static_cast<int>(i / width);
    const auto visit = [&](int nx, int ny) {
      const size_t n = regions.index(nx, ny);
      if (regions.region[n] == regions.region[i] && distance[n] == kUnreached) {
        distance[n] = distance[i] + 1;
        queue.push_back(n);
      }
    };
    if (x > 0) visit(x - 1, y);
    if (x + 1 < width) visit(x + 1, y);
    if (y > 0) visit(x, y - 1);
    if (y + 1 < height) visit(x, y + 1);
  }
  return distance;
}

}  // namespace

HaloMeasure measureHalos(const ScalarImage& sceneValue, const FaceIdImage& faces,
                         const ScalarImage& displayValue, const HaloOptions& options) {
  if (sceneValue.width != faces.width || sceneValue.height != faces.height ||
      displayValue.width != faces.width || displayValue.height != faces.height) {
    throw std::invalid_argument("halo measure: the images differ in size");
  }
  if (options.band < 1 || options.farDistance < options.band) {
    throw std::invalid_argument("halo measure: need 1 <= band <= farDistance");
  }
  const RegionMap regions = findRegions(faces);
  const std::vector<int> distance = distanceFromStrongEdges(regions, sceneValue, options.edgeRatio);
  std::vector<RegionSums> sums(regions.count, RegionSums{std::vector<double>(options.band, 0.0),
                                                         std::vector<int>(options.band, 0)});
  // Pixels the display holds at its black carry no halo (an umbra at the floor) and would bend
  // the far pixels' line: only those above the image's darkest display value (by 5 %) count. A
  // display's white needs no such care: far pixels at white give a flat line, and a halo may
  // well reach white.
  float darkest = HUGE_VALF;
  for (float v : displayValue.values) {
    if (v > 0) darkest = std::min(darkest, v);
  }
  const double floor = darkest * (1 + kFloorMargin);
  const auto counted = [&](size_t i) {
    return distance[i] != kUnreached && sceneValue.values[i] > 0 && displayValue.values[i] > floor;
  };
  for (size_t i = 0; i < distance.size(); ++i) {
    if (!counted(i) || distance[i] < options.farDistance) continue;
    RegionSums& s = sums[regions.region[i]];
    const double x = std::log(sceneValue.values[i]), y = std::log(displayValue.values[i]);
    s.sx += x, s.sy += y, s.sxx += x * x, s.sxy += x * y, ++s.farCount;
    s.lowest = std::min(s.lowest, x), s.highest = std::max(s.highest, x);
  }
  for (RegionSums& s : sums) {
    if (s.farCount == 0) continue;
    const double n = s.farCount, meanX = s.sx / n, meanY = s.sy / n;
    const double varX = std::max(0.0, s.sxx / n - meanX * meanX);
    if (varX > kFlatLogSpread * kFlatLogSpread) s.b = (s.sxy / n - meanX * meanY) / varX;
    s.a = meanY - s.b * meanX;
  }
  for (size_t i = 0; i < distance.size(); ++i) {
    if (!counted(i) || distance[i] >= options.band) continue;
    RegionSums& s = sums[regions.region[i]];
    // Only scene values the far pixels also have: the line is not extrapolated (into an umbra,
    // where a display's black floor is no halo).
    const double x = std::log(sceneValue.values[i]);
    if (x < s.lowest - kFlatLogSpread || x > s.highest + kFlatLogSpread) continue;
    const double predicted = std::exp(s.a + s.b * x);
    s.nearRatio[distance[i]] += displayValue.values[i] / predicted, ++s.nearCount[distance[i]];
  }
  HaloMeasure measure;
  double weightedDeviation = 0, weight = 0;
  for (const RegionSums& s : sums) {
    int near = 0;
    for (int c : s.nearCount) near += c;
    if (near < options.minimumPixels || s.farCount < options.minimumPixels) continue;
    ++measure.regions;
    double deviationSum = 0;
    for (int d = 0; d < options.band; ++d) {
      if (s.nearCount[d] < options.minimumPixels) continue;
      const double relative = s.nearRatio[d] / s.nearCount[d] - 1;
      measure.overshoot = std::max(measure.overshoot, relative);
      measure.undershoot = std::max(measure.undershoot, -relative);
      deviationSum += std::abs(relative) * s.nearCount[d];
    }
    weightedDeviation += deviationSum;
    weight += near;
  }
  measure.meanDeviation = weight > 0 ? weightedDeviation / weight : 0;
  return measure;
}

}  // namespace penumbra
