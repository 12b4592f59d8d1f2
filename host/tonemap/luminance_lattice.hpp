#pragma once
// The constraint map's variables on a lattice of luminance levels (docs/tonemap.md, "What it
// does"): each region (one visible part of one face) is shown as one curve of its own Space-0
// luminance, log V = Φ_r(ℓ), piecewise linear between knots at most kLevelStep of ℓ = log V₀
// apart, from the region's darkest pixel to its brightest. The knots' log V are the unknowns; the
// hierarchy's rows are written on them:
//   strong  every 4-adjacent pixel pair across an edge: Φ_r(ℓ_p) − Φ_s(ℓ_q) = levelEdgeTarget(ℓ_p
//           − ℓ_q), each side's Φ interpolated between its two knots (weight below);
//   medium  each knot step: Φ_r(ℓ_{k+1}) − Φ_r(ℓ_k) = (ℓ_{k+1} − ℓ_k)·levelInsideFactor(G), G
//           the log gradient of the region's pixels at that level (Fattal et al.'s attenuation
//           per level);
//   weak    every knot at its Space-3 value;
//   required  log LowerBound ≤ Φ ≤ 0 at every knot, hence at every pixel.
// Why levels and not places: a pixel's display value is a function of its own luminance and its
// region alone, so no pixel near an edge is shown otherwise than a pixel of the same luminance far
// from it — a halo cannot form — and a region's gentle gradients are raised wherever they are, by
// the same factor at the same level.
#include <Eigen/Core>
#include <vector>

#include "image/images.hpp"
#include "tonemap/constraint_system.hpp"
#include "tonemap/display_spaces.hpp"
#include "tonemap/log_scene.hpp"
#include "tonemap/region_map.hpp"

namespace penumbra {

// Largest knot spacing in log V₀: 5 %; a region's range is cut into equal steps of at most this,
// so that its darkest and brightest pixels lie on knots. Finer (2.5 %) or coarser (10 %) lattices
// gave lower TMQI S on the office (docs/tonemap.md).
constexpr double kLevelStep = 0.05;
// The pixel unit of the row weights: a medium or weak row backed by n pixels weighs
// √(n / kLevelCellPixels) times its level's weight, as the image lattice's rows of those pixels
// did together (one vertex per 8 × 8 pixels), so --medium and --weak keep their meaning.
constexpr double kLevelCellPixels = 64;

// An edge row's weight is strong / √max(|target|, kLevelEdgeWeightFloor): where the edges in
// a row of regions ask for more than the display holds, least squares then takes from each the
// same fraction of its target (not the same amount), so that no faint edge is reversed
// (ToneMap.StaircaseShowsEveryEdgeCompressedByOneFactor). The floor (a target of 0.2 in log)
// holds two coplanar faces that continue each other (target 0) to each other at 2.2 × strong.
constexpr double kLevelEdgeWeightFloor = 0.2;

struct LuminanceLattice {
  std::vector<int> first;    // per region: the variable of its darkest knot
  std::vector<int> count;    // per region: its knots
  std::vector<double> low;   // per region: ℓ at its darkest knot
  std::vector<double> step;  // per region: ℓ between its knots
  int variables = 0;

  // The knot at or below ℓ in region r and the weight of the next one (0 at the ends).
  struct Position {
    int knot = 0;
    double weight = 0;
  };
  Position locate(int region, double logValue) const;
  // Φ at a position, from the knots' values.
  double valueAt(const Eigen::VectorXd& values, Position p) const {
    return p.weight > 0 ? (1 - p.weight) * values[p.knot] + p.weight * values[p.knot + 1]
                        : values[p.knot];
  }
};

LuminanceLattice buildLuminanceLattice(const RegionMap& regions, const LogScene& scene);

ConstraintSystem buildLevelConstraintSystem(const LuminanceLattice& lattice,
                                            const RegionMap& regions, const LogScene& scene,
                                            const ConstraintWeights& weights);

// Every pixel's display V from the solved knots: Φ_r(ℓ) of its region, held to [LowerBound, 1];
// a pixel on no surface shows the exposure curve (Space 3).
ScalarImage levelDisplayValues(const LuminanceLattice& lattice, const RegionMap& regions,
                               const DisplaySpaces& spaces, const LogScene& scene,
                               const Eigen::VectorXd& values);

}  // namespace penumbra
