// Scenes for the scale check (bench/scale_rss.sh, docs/reliability.md "Scale"),
// written to stdout:
//
//   scale_scene POINTS            an empty 6 × 4 × 3 m room, one 3000 lm panel, a rect grid over
//                                 the floor with about POINTS points
//   scale_scene POINTS SOLIDS     a 60 × 40 × 4 m hall holding SOLIDS boxes (pallets and crates,
//                                 0.3 to 1.2 m high, on a regular lattice, heights varying), lit
//                                 by eight 0.6 × 0.6 m panels; a rect grid at 0.8 m over the
//                                 whole floor (points inside the taller boxes are inside solids)
//
// The spacing is sqrt(area / POINTS) rounded up to three significant digits, so the grid has a
// little fewer points than asked (100 492 for 10^5, 1 000 825 for 10^6, 9 991 051 for 10^7 in the
// small room): the figures docs/reliability.md compares with.
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

double spacingFor(double area, double points) {
  const double p = std::sqrt(area / points);
  const double unit = std::pow(10.0, std::floor(std::log10(p)) - 2.0);
  return std::ceil(p / unit - 1e-9) * unit;
}

std::string emptyRoom(double points) {
  return fmt::format(
      "# bench/scale_scene {:.0f}: empty room, one panel, a rect grid over the floor\n"
      "penumbra: 1\n"
      "room: {{size: [6, 4, 3]}}\n"
      "sources:\n"
      "  - {{name: p, rect: {{center: [3, 2, 2.99], size: [0.6, 0.6], normal: [0, 0, -1]}}, "
      "flux: 3000}}\n"
      "grids:\n"
      "  - {{name: floor, rect: {{origin: [0, 0, 0], u: [6, 0, 0], v: [0, 4, 0]}}, spacing: "
      "{:.3g}}}\n",
      points, spacingFor(24.0, points));
}

std::string hall(double points, int solids) {
  constexpr double kWidth = 60.0, kDepth = 40.0, kHeight = 4.0;
  // A lattice of columns × rows cells as square as the hall, one box per cell, in row order.
  const int columns = static_cast<int>(std::ceil(std::sqrt(solids * kWidth / kDepth)));
  const int rows = (solids + columns - 1) / columns;
  const double cellX = kWidth / columns, cellY = kDepth / rows;
  std::string yaml = fmt::format(
      "# bench/scale_scene {:.0f} {}: a {} x {} x {} m hall, {} boxes, eight panels\n"
      "penumbra: 1\n"
      "room: {{size: [{}, {}, {}]}}\n"
      "solids:\n",
      points, solids, kWidth, kDepth, kHeight, solids, kWidth, kDepth, kHeight);
  unsigned state = 12345u;  // a fixed linear congruential sequence: the same hall every time
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / static_cast<double>(1u << 24);
  };
  for (int k = 0; k < solids; ++k) {
    const int c = k % columns, r = k / columns;
    const double w = (0.35 + 0.3 * next()) * cellX, d = (0.35 + 0.3 * next()) * cellY;
    const double x = (c + 0.5) * cellX - w / 2, y = (r + 0.5) * cellY - d / 2;
    const double h = 0.3 + 0.9 * next();
    yaml += fmt::format(
        "  - {{name: box-{}, box: {{min: [{:.4f}, {:.4f}, 0], max: [{:.4f}, {:.4f}, {:.3f}]}}}}\n",
        k, x, y, x + w, y + d, h);
  }
  yaml += "sources:\n";
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 2; ++j) {
      yaml += fmt::format(
          "  - {{name: panel-{}-{}, rect: {{center: [{}, {}, {}], size: [0.6, 0.6], normal: [0, 0, "
          "-1]}}, flux: 20000}}\n",
          i, j, 7.5 + 15.0 * i, 10.0 + 20.0 * j, kHeight - 0.01);
    }
  }
  yaml += fmt::format(
      "grids:\n"
      "  - {{name: work-plane, rect: {{origin: [0, 0, 0.8], u: [{}, 0, 0], v: [0, {}, 0]}}, "
      "spacing: {:.3g}}}\n",
      kWidth, kDepth, spacingFor(kWidth * kDepth, points));
  return yaml;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || argc > 3) {
    std::fprintf(stderr, "usage: scale_scene POINTS [SOLIDS] > scene.yaml\n");
    return 1;
  }
  const double points = std::atof(argv[1]);
  const int solids = argc == 3 ? std::atoi(argv[2]) : 0;
  if (!(points >= 1.0) || solids < 0) {
    std::fprintf(stderr, "scale_scene: POINTS must be at least 1 and SOLIDS at least 0\n");
    return 1;
  }
  const std::string yaml = solids == 0 ? emptyRoom(points) : hall(points, solids);
  std::fwrite(yaml.data(), 1, yaml.size(), stdout);
  return 0;
}
