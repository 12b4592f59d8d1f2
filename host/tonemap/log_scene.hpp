#pragma once
// The scene in the log domain, as the constraint rows ask for it (docs/tonemap.md, "What it
// does"). The unknowns are x = log V (display V, a share of the display's white); every row asks
// for a difference of x across an edge or inside a region, or for x itself:
//   across an edge   the scene's log ratio d, compressed above a knee (edgeTarget): the ratio
//                    cap applied softly, so that a window or a luminaire beside a wall asks for
//                    a visible step, not for the display's whole range;
//   inside a region  the log ratio between two vertices, raised where it is gentle and
//                    compressed where it is steep (insideTarget): the gradient-domain
//                    attenuation of Fattal, Lischinski & Werman (2002) on the region's lattice;
//   weak             Space 3: a global exposure curve (exposedValue), not the linear eq. 4.12.
#include <cstdint>
#include <vector>

#include "tonemap/display_spaces.hpp"
#include "tonemap/region_map.hpp"

namespace penumbra {

struct LogScene {
  std::vector<float> logValue;           // per pixel: log V₀, floored at 1e-4 of MaxRGB
  std::vector<float> gradientMagnitude;  // per pixel: |∇ log V₀| within its region, per pixel
  double logWhite = 0;  // log of the V₀ where the curve's y = 1: the clip map's automatic white
  double logLowerBound = 0;  // log LowerBound: the darkest display V

  // The display log ratio asked for across an edge whose scene log ratio is d (sign kept).
  double edgeTarget(double d) const;
  // The display log ratio asked for between two vertices of one region, at pixels a and b
  // `distance` pixels apart, whose scene log ratio is d: d·(G/k)^(β−1) with G the log gradient's
  // magnitude there (Fattal et al.'s attenuation, eq. 3, with k = kInsideKnee and
  // β = kInsideExponent). One factor per place, whatever the pair's direction, so that the rows
  // of a smooth region agree with each other.
  double insideTarget(double d, double distance, size_t a, size_t b) const;
  // Space 3 at a pixel: log of LowerBound + (1 − LowerBound)·y/(1 + y), y = V₀ / white.
  double exposedValue(size_t pixel) const;
  // Space 3 of a log V₀.
  double exposedLogValue(double logValue) const;

  // The luminance lattice's targets (luminance_lattice.hpp). Across an edge: the attenuation of
  // the inside rows with the edge's own log ratio as its gradient (an edge is a gradient of |d|
  // per pixel), sign(d)·k_e^(1−β)|d|^β, at most kLevelEdgeCap: a faint edge (a corner between two
  // walls) is raised as a gentle gradient is, a strong one compressed.
  double levelEdgeTarget(double d) const;
  // Inside a region, at a level whose pixels have the log gradient G: the factor (G/k)^(β−1).
  double levelInsideFactor(double gradient) const;
};

// Across an edge: log ratios up to kEdgeKnee are kept, larger ones shown as
// kEdgeKnee·(d/kEdgeKnee)^kEdgeExponent, and none above kEdgeCap (e = 2.7:1).
constexpr double kEdgeKnee = 0.5, kEdgeExponent = 0.5, kEdgeCap = 1.0;
// Inside a region: a log gradient g per pixel is shown as kInsideKnee·(g/kInsideKnee)^
// kInsideExponent: raised below 3 % per pixel, compressed above.
constexpr double kInsideKnee = 0.03, kInsideExponent = 0.7;
// The luminance lattice's attenuation: k = kLevelKnee, β = kLevelExponent inside a region,
// k_e = kLevelEdgeKnee across an edge, and no edge shown above kLevelEdgeCap (e² = 7.4:1). Chosen
// on the TMQI bench (docs/tonemap.md, "Choosing the constants").
constexpr double kLevelKnee = 0.1, kLevelExponent = 0.65, kLevelEdgeKnee = 3, kLevelEdgeCap = 2;
LogScene logScene(const DisplaySpaces& spaces, const RegionMap& regions);

}  // namespace penumbra
