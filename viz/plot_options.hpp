#pragma once
// What `penumbra plot` (and `penumbra grid --plot`) is asked for. Free of CLI11 and VTK so that
// the parsing (plot_cli.cpp) and the drawing stay apart.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace penumbra::viz {

enum class Palette {
  Viridis,     // perceptually uniform, readable in grey and by colour-blind readers (default)
  FalseColor,  // after Radiance's falsecolor: purple, blue, teal, green, brown, red, orange, yellow
};

// How illuminance becomes colour; the same for every picture of a run, so that variants plotted
// with the same --range can be compared side by side.
struct LegendOptions {
  std::optional<std::pair<double, double>> range;  // lx; none: from the data
  bool log = false;
  Palette palette = Palette::Viridis;
};

struct PlotOptions {
  std::filesystem::path folder;  // the output directory of `penumbra grid`
  LegendOptions legend;
  std::vector<double> isolux;   // lx, ascending; empty: a 1-2-5 series from the data
  bool noIsolux = false;        // --isolux none
  int width = 1600;             // px, of every PNG
  double surfaceSpacing = 0.0;  // m between samples on room surfaces; 0: from the scene's size
  int isobands = 0;             // > 0: also <grid>.svg, iso-bands of E (about this many bands)
  std::string device = "auto";  // OpenCL device for the surfaces' illuminance
  double ugrLimit = 19.0;       // UGR maps (a glare folder): the EN 12464-1 limit drawn
  bool quiet = false;
};

}  // namespace penumbra::viz
