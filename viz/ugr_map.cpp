#include "viz/ugr_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <stdexcept>

#include "output/result_files.hpp"

namespace penumbra::viz {
namespace {

struct Eye {
  Vec3 position = Vec3::Zero();
  std::optional<double> ugr;
};

Vec3 vectorOf(const nlohmann::json& xyz) {
  return {xyz.at(0).get<double>(), xyz.at(1).get<double>(), xyz.at(2).get<double>()};
}

}  // namespace

std::vector<UgrGrid> ugrGrids(const nlohmann::json& summary) {
  if (!summary.contains("observers") || !summary.at("observers").is_array()) {
    throw std::runtime_error("not the summary.json of `penumbra glare` (no observers)");
  }
  // entry -> (column, row) -> eye, in scene order of the entries.
  std::vector<std::string> order;
  std::map<std::string, std::map<std::pair<int, int>, Eye>> entries;
  static const std::regex kGridName(R"(^(.*)\[(\d+),(\d+)\]$)");
  for (const nlohmann::json& o : summary.at("observers")) {
    std::smatch match;
    const std::string name = o.at("name").get<std::string>();
    if (!std::regex_match(name, match, kGridName)) continue;
    const std::string entry = o.at("entry").get<std::string>();
    if (!entries.count(entry)) order.push_back(entry);
    Eye eye{vectorOf(o.at("eye_m")), std::nullopt};
    if (!o.at("UGR_max").is_null()) eye.ugr = o.at("UGR_max").get<double>();
    entries[entry][{std::stoi(match[2].str()), std::stoi(match[3].str())}] = eye;
  }
  std::vector<UgrGrid> grids;
  for (const std::string& entry : order) {
    const auto& eyes = entries.at(entry);
    // The scene numbers columns and rows from 1; the lattice counts from its first eye.
    int firstColumn = eyes.begin()->first.first, firstRow = eyes.begin()->first.second;
    int lastColumn = firstColumn, lastRow = firstRow;
    for (const auto& [at, eye] : eyes) {
      firstColumn = std::min(firstColumn, at.first);
      firstRow = std::min(firstRow, at.second);
      lastColumn = std::max(lastColumn, at.first);
      lastRow = std::max(lastRow, at.second);
    }
    const int columns = lastColumn - firstColumn + 1, rows = lastRow - firstRow + 1;
    if (columns < 2 || rows < 2 || eyes.size() != static_cast<std::size_t>(columns * rows))
      continue;
    UgrGrid grid;
    grid.entry = entry;
    PlanarField& f = grid.field;
    f.name = entry;
    f.columns = columns;
    f.rows = rows;
    f.first = eyes.at({firstColumn, firstRow}).position;
    f.uStep = eyes.at({firstColumn + 1, firstRow}).position - f.first;
    f.vStep = eyes.at({firstColumn, firstRow + 1}).position - f.first;
    f.normal = f.uStep.cross(f.vStep).normalized();
    f.illuminance.resize(eyes.size(), 0.0);
    f.valid.resize(eyes.size(), 0);
    for (const auto& [at, eye] : eyes) {
      const std::size_t i = f.index(at.first - firstColumn, at.second - firstRow);
      if (eye.ugr) {
        f.illuminance[i] = *eye.ugr;
        f.valid[i] = 1;
      } else {
        ++grid.undefined;
      }
    }
    f.plot = plotPlaneFor(f);
    grids.push_back(std::move(grid));
  }
  return grids;
}

std::string ugrMapFileName(const std::string& entry) {
  return gridFileStem(entry) + "-ugr.png";
}

HeatMapFigure drawUgrMap(const UgrGrid& grid, const Scene& scene, double limit, int width,
                         const std::string& subtitle, const std::filesystem::path& png) {
  const PlanarField& f = grid.field;
  double lo = 0.0, hi = 0.0;
  int rated = 0, meeting = 0;
  for (std::size_t i = 0; i < f.illuminance.size(); ++i) {
    if (!f.valid[i]) continue;
    const double ugr = f.illuminance[i];
    lo = rated == 0 ? ugr : std::min(lo, ugr);
    hi = rated == 0 ? ugr : std::max(hi, ugr);
    ++rated;
    if (ugr <= limit) ++meeting;
  }
  HeatMapStyle style;
  style.scale.min = std::floor(std::min(lo, limit) - 1.0);
  style.scale.max = std::ceil(std::max(hi, limit) + 1.0);
  if (lo < limit && hi > limit) style.isolux = {limit};
  style.width = width;
  style.subtitle = subtitle;
  FieldQuantity& q = style.quantity;
  q.title = "UGR_max over the lines of sight (CIE 117, L_b from the interreflection)";
  q.extremeLabel = "UGR ";
  q.unit = "";
  q.levelPrefix = "UGR_L ";
  q.legendTitle = "UGR [-]";
  q.metricsLine = fmt::format(
      "{} eyes: UGR_max {:.1f} to {:.1f}    EN 12464-1 limit UGR_L {:g} met at {} of {}{}",
      f.illuminance.size(), lo, hi, limit, meeting, rated,
      grid.undefined > 0 ? fmt::format("    {} eyes without a UGR (blank)", grid.undefined)
                         : std::string());
  GridMetrics none;
  return drawHeatMap(f, none, scene, style, png);
}

}  // namespace penumbra::viz
