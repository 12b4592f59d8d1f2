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

// Far pixels are binned by log scene value; a near pixel's prediction is the least-squares line
// log display = a + b log scene through the far pixels within kLocalSpan of its own log scene
// value: the region's own relation at that luminance, whatever its shape over the whole region.
constexpr double kBinWidth = 0.01;
constexpr int kLocalBins = 10;  // kLocalSpan = 0.1 in log scene value (±10 %)
// Below this variance of the local far pixels' log scene values (a flat region) they fix no
// slope: b = 1, a pure gain.
constexpr double kFlatLogVariance = 1e-6;

struct LineSums {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  void add(const LineSums& o) { n += o.n, sx += o.sx, sy += o.sy, sxx += o.sxx, sxy += o.sxy; }
};

struct RegionSums {
  std::vector<double> nearRatio;  // per distance 0 … band-1: Σ display / predicted
  std::vector<int> nearCount;
  int farCount = 0;
  double lowest = HUGE_VAL, highest = -HUGE_VAL;  // log scene range of the far pixels
  std::vector<LineSums> bins;                     // far pixels from `lowest` every kBinWidth
};
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
  RegionSums empty;
  empty.nearRatio.assign(options.band, 0.0);
  empty.nearCount.assign(options.band, 0);
  std::vector<RegionSums> sums(regions.count, empty);
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
  const auto isFar = [&](size_t i) { return counted(i) && distance[i] >= options.farDistance; };
  for (size_t i = 0; i < distance.size(); ++i) {
    if (!isFar(i)) continue;
    RegionSums& s = sums[regions.region[i]];
    const double x = std::log(sceneValue.values[i]);
    s.lowest = std::min(s.lowest, x), s.highest = std::max(s.highest, x), ++s.farCount;
  }
  for (RegionSums& s : sums) {
    if (s.farCount > 0) s.bins.resize(static_cast<size_t>((s.highest - s.lowest) / kBinWidth) + 1);
  }
  for (size_t i = 0; i < distance.size(); ++i) {
    if (!isFar(i)) continue;
    RegionSums& s = sums[regions.region[i]];
    const double x = std::log(sceneValue.values[i]), y = std::log(displayValue.values[i]);
    LineSums& bin = s.bins[std::min(s.bins.size() - 1, size_t((x - s.lowest) / kBinWidth))];
    bin.n += 1, bin.sx += x, bin.sy += y, bin.sxx += x * x, bin.sxy += x * y;
  }
  for (size_t i = 0; i < distance.size(); ++i) {
    if (!counted(i) || distance[i] >= options.band) continue;
    RegionSums& s = sums[regions.region[i]];
    if (s.bins.empty()) continue;
    // Only scene values the far pixels also have, within kLocalSpan: the relation is not
    // extrapolated (into an umbra, where a display's black floor is no halo).
    const double x = std::log(sceneValue.values[i]);
    const long at = static_cast<long>(std::floor((x - s.lowest) / kBinWidth));
    LineSums local;
    for (long k = std::max(0L, at - kLocalBins);
         k <= std::min(static_cast<long>(s.bins.size()) - 1, at + kLocalBins); ++k) {
      local.add(s.bins[k]);
    }
    if (local.n < options.minimumPixels) continue;
    const double meanX = local.sx / local.n, meanY = local.sy / local.n;
    const double varX = std::max(0.0, local.sxx / local.n - meanX * meanX);
    const double b = varX > kFlatLogVariance ? (local.sxy / local.n - meanX * meanY) / varX : 1.0;
    const double predicted = std::exp(meanY + b * (x - meanX));
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
