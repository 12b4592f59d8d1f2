#include "tonemap/luminance_lattice.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace penumbra {
namespace {

// What a knot step is shown as follows from the log gradient of the region's pixels at that
// level: the mean |∇ℓ| of the pixels in the step, or, where larger, the mean slope of the
// 4-adjacent pixel pairs of the region whose values span it (a shadow edge inside a face, which
// steps over levels no pixel has). The pairs' own slope is what the image lattice's rows used
// between two vertices across such an edge.
struct LevelGradients {
  std::vector<double> pixels, gradientSum, spanWeight, spanSlopeSum;
  explicit LevelGradients(int variables)
      : pixels(variables, 0),
        gradientSum(variables, 0),
        spanWeight(variables, 0),
        spanSlopeSum(variables, 0) {}

  double at(int knot, double step) const {
    const double own = pixels[knot] > 0 ? gradientSum[knot] / pixels[knot] : 0.0;
    const double spanned = spanWeight[knot] > 0 ? spanSlopeSum[knot] / spanWeight[knot] : step;
    return std::max(own, spanned);
  }
};

LevelGradients levelGradients(const LuminanceLattice& lattice, const RegionMap& regions,
                              const LogScene& scene) {
  LevelGradients g(lattice.variables);
  const std::vector<float>& l = scene.logValue;
  for (size_t i = 0; i < l.size(); ++i) {
    const int r = regions.region[i];
    if (r == RegionMap::kNone) continue;
    const int knot = lattice.locate(r, l[i]).knot;
    g.pixels[knot] += 1;
    g.gradientSum[knot] += scene.gradientMagnitude[i];
  }
  // A pair spanning levels t0 < t1 (in steps from the region's darkest knot) adds its slope to
  // each step it overlaps, weighted by the overlap.
  const auto span = [&](size_t a, size_t b) {
    const int r = regions.region[a];
    if (r == RegionMap::kNone || regions.region[b] != r) return;
    const double la = std::min(l[a], l[b]), lb = std::max(l[a], l[b]);
    if (!(lb > la)) return;
    const double t0 = (la - lattice.low[r]) / lattice.step[r];
    const double t1 = (lb - lattice.low[r]) / lattice.step[r];
    for (int k = std::max(0, static_cast<int>(t0)); k + 1 < lattice.count[r] && k < t1; ++k) {
      const double overlap = std::min(t1, k + 1.0) - std::max(t0, double(k));
      if (overlap <= 0) continue;
      g.spanWeight[lattice.first[r] + k] += overlap;
      g.spanSlopeSum[lattice.first[r] + k] += overlap * (lb - la);
    }
  };
  forEachAdjacentPair(regions.width, regions.height, span);
  return g;
}

}  // namespace

LuminanceLattice::Position LuminanceLattice::locate(int region, double logValue) const {
  const double t = (logValue - low[region]) / step[region];
  const int last = count[region] - 1;
  if (!(t > 0)) return {first[region], 0.0};
  if (t >= last) return {first[region] + last, 0.0};
  const int k = static_cast<int>(t);
  return {first[region] + k, t - k};
}

LuminanceLattice buildLuminanceLattice(const RegionMap& regions, const LogScene& scene) {
  LuminanceLattice lattice;
  std::vector<double> lowest(regions.count, std::numeric_limits<double>::infinity());
  std::vector<double> highest(regions.count, -std::numeric_limits<double>::infinity());
  for (size_t i = 0; i < scene.logValue.size(); ++i) {
    const int r = regions.region[i];
    if (r == RegionMap::kNone) continue;
    lowest[r] = std::min<double>(lowest[r], scene.logValue[i]);
    highest[r] = std::max<double>(highest[r], scene.logValue[i]);
  }
  lattice.first.resize(regions.count);
  lattice.count.resize(regions.count);
  lattice.low.resize(regions.count);
  lattice.step.resize(regions.count);
  for (int r = 0; r < regions.count; ++r) {
    const double range = highest[r] - lowest[r];
    const int steps = static_cast<int>(std::ceil(range / kLevelStep));
    lattice.low[r] = lowest[r];
    lattice.step[r] = steps > 0 ? range / steps : kLevelStep;
    lattice.count[r] = steps + 1;
    lattice.first[r] = lattice.variables;
    lattice.variables += lattice.count[r];
  }
  return lattice;
}

ConstraintSystem buildLevelConstraintSystem(const LuminanceLattice& lattice,
                                            const RegionMap& regions, const LogScene& scene,
                                            const ConstraintWeights& weights) {
  const std::vector<float>& l = scene.logValue;
  const LevelGradients gradients = levelGradients(lattice, regions, scene);
  // A row backed by more pixels weighs more, as √(pixels / cell): the image lattice had one
  // vertex, and its rows, per cell.
  const auto backed = [](double pixels) {
    return std::sqrt(std::max(1.0, pixels / kLevelCellPixels));
  };
  ConstraintRows rows;
  ConstraintSystem system;

  // Strong: every 4-adjacent pixel pair across an edge, each side's Φ between its two knots.
  const auto edge = [&](size_t a, size_t b) {
    const int ra = regions.region[a], rb = regions.region[b];
    if (ra == rb || ra == RegionMap::kNone || rb == RegionMap::kNone) return;
    const LuminanceLattice::Position pa = lattice.locate(ra, l[a]), pb = lattice.locate(rb, l[b]);
    const double target = scene.levelEdgeTarget(double(l[a]) - l[b]);
    rows.add(ConstraintLevel::Strong,
             weights.strong / std::sqrt(std::max(std::abs(target), kLevelEdgeWeightFloor)),
             {{pa.knot, 1 - pa.weight},
              {pa.knot + (pa.weight > 0), pa.weight},
              {pb.knot, -(1 - pb.weight)},
              {pb.knot + (pb.weight > 0), -pb.weight}},
             target);
  };
  forEachAdjacentPair(regions.width, regions.height, edge);

  // Medium: each knot step, the attenuated scene step.
  for (int r = 0; r < regions.count; ++r) {
    for (int k = lattice.first[r]; k + 1 < lattice.first[r] + lattice.count[r]; ++k) {
      const double factor =
          scene.levelInsideFactor(std::max(gradients.at(k, lattice.step[r]), 1e-6));
      rows.add(ConstraintLevel::Medium,
               weights.medium * backed(gradients.pixels[k] + gradients.pixels[k + 1]),
               {{k + 1, 1.0}, {k, -1.0}}, lattice.step[r] * factor);
    }
  }

  // Weak: every knot at its Space-3 value, also the solver's start.
  system.start.resize(lattice.variables);
  for (int r = 0; r < regions.count; ++r) {
    for (int i = 0; i < lattice.count[r]; ++i) {
      const int k = lattice.first[r] + i;
      system.start[k] = scene.exposedLogValue(lattice.low[r] + i * lattice.step[r]);
      rows.add(ConstraintLevel::Weak, weights.weak * backed(gradients.pixels[k]), {{k, 1.0}},
               system.start[k]);
    }
  }
  rows.fill(system, lattice.variables, scene.logLowerBound);
  return system;
}

ScalarImage levelDisplayValues(const LuminanceLattice& lattice, const RegionMap& regions,
                               const DisplaySpaces& spaces, const LogScene& scene,
                               const Eigen::VectorXd& values) {
  ScalarImage display(regions.width, regions.height);
  for (size_t i = 0; i < scene.logValue.size(); ++i) {
    const int r = regions.region[i];
    const double value = r == RegionMap::kNone
                             ? scene.exposedValue(i)
                             : lattice.valueAt(values, lattice.locate(r, scene.logValue[i]));
    display.values[i] = boundedDisplayValue(std::exp(value), spaces.lowerBound);
  }
  return display;
}

}  // namespace penumbra
