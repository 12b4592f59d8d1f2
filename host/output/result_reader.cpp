#include "output/result_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include <nlohmann/json.hpp>

#include "grid/grid_metrics.hpp"
#include "output/grid_rows.hpp"
#include "output/result_files.hpp"

namespace penumbra {

namespace {

namespace fs = std::filesystem;

// One CSV record; RFC 4180 quotes (the only field that can have them is `inside`).
std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// from_chars reads the shortest round-trip form back to the very same double.
double parseNumber(const std::string& text, const std::string& where) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end) {
    throw std::runtime_error(fmt::format("{}: '{}' is not a number", where, text));
  }
  return value;
}

double numberOrNaN(const nlohmann::json& value) {
  return value.is_number() ? value.get<double>() : std::numeric_limits<double>::quiet_NaN();
}

// summary.json's "parameters": the values the scene's parameters had in the run (defaults or
// --set). Runs written before parameters existed have none: the scene then loads with its
// defaults, which is what those runs used.
ParameterValues readParameters(const nlohmann::json& summary, const fs::path& file) {
  ParameterValues values;
  if (!summary.contains("parameters")) return values;
  const nlohmann::json& parameters = summary["parameters"];
  if (!parameters.is_object()) {
    throw std::runtime_error(
        fmt::format("{}: parameters: expected an object of name: value", file.string()));
  }
  for (const auto& [name, value] : parameters.items()) {
    if (!value.is_number()) {
      throw std::runtime_error(fmt::format("{}: parameters.{}: expected a number, found {}",
                                           file.string(), name, value.dump()));
    }
    values.push_back({name, value.get<double>()});
  }
  return values;
}

// The daylight factor figures of a grid whose CSV has DF columns: recomputed from them (points
// inside solids left out, as the run did), with E_h and E_v,d,med from summary.json.
DaylightMetrics readDaylight(const nlohmann::json& entry, const GridReport& grid,
                             const fs::path& csv) {
  if (!entry.contains("daylight_factor")) {
    throw std::runtime_error(fmt::format(
        "{} has daylight factor columns, but summary.json gives its grid no daylight_factor",
        csv.string()));
  }
  const nlohmann::json& j = entry.at("daylight_factor");
  std::optional<double> median;
  if (j.contains("en17037")) median = j.at("en17037").at("median_diffuse_illuminance_lx");
  std::vector<double> factors, direct;
  double skySum = 0.0, externalSum = 0.0;  // %, the components
  for (std::size_t i = 0; i < grid.daylightFactor.size(); ++i) {
    if (!grid.insideSolids[i].empty()) continue;
    factors.push_back(grid.daylightFactor[i]);
    if (!grid.daylightFactorDirect.empty()) direct.push_back(grid.daylightFactorDirect[i]);
    if (!grid.skyComponentFactor.empty()) {
      skySum += grid.skyComponentFactor[i];
      externalSum += grid.externalComponentFactor[i];
    }
  }
  const auto counted = static_cast<double>(factors.size());
  DaylightMetrics metrics = daylightFactorMetrics(
      std::move(factors), direct, j.at("outdoor_horizontal_illuminance_lx").get<double>(), median);
  if (!grid.skyComponentFactor.empty() && counted > 0.0)
    metrics.components = daylightComponents(metrics, skySum / counted, externalSum / counted);
  // Without faces_up the grid counts as facing up: its verdict rests on the en17037 key alone.
  metrics.horizontal = j.value("faces_up", true);
  return metrics;
}

GridReport readGrid(const nlohmann::json& entry, const fs::path& directory) {
  GridReport grid;
  grid.name = entry.at("name").get<std::string>();
  // Runs written before plots existed have no layout: their grids are read as point lists.
  grid.kind = gridKindFromName(entry.value("kind", std::string("points")));
  if (grid.kind != GridKind::Points) {
    grid.columns = entry.at("columns").get<int>();
    grid.rows = entry.at("rows").get<int>();
  }
  grid.seconds = entry.value("time_s", 0.0);
  const fs::path csv = directory / entry.at("csv").get<std::string>();
  std::ifstream in(csv, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + csv.string());
  readGridCsv(in, csv.string(), grid);

  const std::size_t expected = entry.at("points").get<std::size_t>();
  if (grid.points.size() != expected) {
    throw std::runtime_error(fmt::format("{}: {} rows, but summary.json says {} points",
                                         csv.string(), grid.points.size(), expected));
  }
  if (grid.kind != GridKind::Points &&
      static_cast<std::size_t>(grid.columns) * grid.rows != grid.points.size()) {
    throw std::runtime_error(fmt::format("{}: {} rows, but the grid is {} × {}", csv.string(),
                                         grid.points.size(), grid.columns, grid.rows));
  }
  std::vector<int> inside;
  for (const std::string& solid : grid.insideSolids) inside.push_back(solid.empty() ? -1 : 0);
  const double spacing = entry.contains("spacing_m") ? numberOrNaN(entry["spacing_m"]) : 0.0;
  grid.metrics = gridMetrics(grid.illuminance, inside, std::isnan(spacing) ? 0.0 : spacing);
  if (!grid.direct.empty()) {
    grid.directMetrics = gridMetrics(grid.direct, inside, std::isnan(spacing) ? 0.0 : spacing);
  }
  if (!grid.daylightFactor.empty()) grid.daylight = readDaylight(entry, grid, csv);
  return grid;
}

}  // namespace

nlohmann::json readSummary(const fs::path& file) {
  std::ifstream in(file);
  if (!in) {
    throw std::runtime_error(fmt::format(
        "{}: no summary.json: is this the output directory of `penumbra grid`?", file.string()));
  }
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(fmt::format("{}: {}", file.string(), e.what()));
  }
}

void readGridCsv(std::istream& in, const std::string& fileName, GridReport& grid) {
  std::string line;
  // The header names the columns: E's parts, the sun and the daylight factor are each optional.
  struct Layout {
    bool withParts, daylight, sun;
    std::string header;  // without the line break
  };
  std::vector<Layout> layouts;
  for (const bool withParts : {false, true})
    for (const bool daylight : {false, true})
      for (const bool sun : {false, true}) {
        const std::string text = gridCsvHeader(withParts, daylight, sun);
        layouts.push_back({withParts, daylight, sun, text.substr(0, text.size() - 1)});
      }
  const bool read = static_cast<bool>(std::getline(in, line));
  const auto layout = std::find_if(layouts.begin(), layouts.end(),
                                   [&](const Layout& l) { return read && line == l.header; });
  if (layout == layouts.end()) {
    std::string headers;
    for (const Layout& l : layouts) headers += (headers.empty() ? "" : ", ") + l.header;
    throw std::runtime_error(
        fmt::format("{}:1: expected one of the headers {}", fileName, headers));
  }
  // x..nz, E (and its two parts), E_sun (and with the parts its reflection), DF (and its two
  // parts and its three components), inside.
  const std::size_t eFields = layout->withParts ? 3 : 1;
  const std::size_t sunColumn = 6 + eFields;
  const std::size_t dfColumn = sunColumn + (layout->sun ? (layout->withParts ? 2 : 1) : 0);
  const std::size_t fields = csvFields(layout->header).size();
  for (int lineNumber = 2; std::getline(in, line); ++lineNumber) {
    if (line.empty()) continue;
    const std::string where = fmt::format("{}:{}", fileName, lineNumber);
    const std::vector<std::string> f = csvFields(line);
    if (f.size() != fields) {
      throw std::runtime_error(fmt::format("{}: {} fields, expected {}", where, f.size(), fields));
    }
    SamplePoint point;
    point.position =
        Vec3(parseNumber(f[0], where), parseNumber(f[1], where), parseNumber(f[2], where));
    point.normal =
        Vec3(parseNumber(f[3], where), parseNumber(f[4], where), parseNumber(f[5], where));
    grid.points.push_back(point);
    grid.illuminance.push_back(parseNumber(f[6], where));
    if (layout->withParts) grid.direct.push_back(parseNumber(f[7], where));
    if (layout->sun) grid.sun.push_back(parseNumber(f[sunColumn], where));
    if (layout->sun && layout->withParts)
      grid.sunReflected.push_back(parseNumber(f[sunColumn + 1], where));
    if (layout->daylight) {
      grid.daylightFactor.push_back(parseNumber(f[dfColumn], where));
      if (layout->withParts) {
        grid.daylightFactorDirect.push_back(parseNumber(f[dfColumn + 1], where));
        grid.skyComponentFactor.push_back(parseNumber(f[dfColumn + 3], where));
        grid.externalComponentFactor.push_back(parseNumber(f[dfColumn + 4], where));
      }
    }
    grid.insideSolids.push_back(f[fields - 1]);
  }
}

namespace {

// The solver's report as writeSummary wrote it (result_files.cpp: interreflectionJson).
InterreflectionReport readInterreflection(const nlohmann::json& summary) {
  const nlohmann::json& j = summary.at("interreflection");
  InterreflectionReport r;
  r.elements = j.at("elements").get<std::size_t>();
  r.elementSize = j.at("element_size_m").get<double>();
  r.nodes = j.value("quadrature_nodes", std::size_t{0});
  r.surfaceArea = j.value("surface_area_m2", 0.0);
  r.residual = j.value("relative_residual", 0.0);
  r.transferReused = j.value("transfer_reused", false);
  r.refinementCapped = j.value("refinement_capped", false);
  r.linearGather = j.value("final_gather", std::string()) == "linear within elements";
  r.linkError = j.value("link_error", 0.0);
  r.links = j.value("links", std::size_t{0});
  r.denseElements = j.value("dense_elements_past_limit", std::size_t{0});
  for (const nlohmann::json& name : j.value("solids_without_material", nlohmann::json::array()))
    r.blackSolids.push_back(name.get<std::string>());
  if (j.contains("timing")) {
    const nlohmann::json& timing = j["timing"];
    r.meshSeconds = timing.value("mesh_s", 0.0);
    r.transferSeconds = timing.value("transfer_s", 0.0);
    r.solveSeconds = timing.value("solve_s", 0.0);
  }
  return r;
}

}  // namespace

RunReport readResults(const fs::path& directory) {
  const nlohmann::json summary = readSummary(directory / "summary.json");
  RunReport run;
  try {
    run.version = summary.value("penumbra_version", std::string());
    const nlohmann::json absolute = summary.value("scene_absolute", nlohmann::json(nullptr));
    run.sceneFile = absolute.is_string() ? fs::path(absolute.get<std::string>())
                                         : fs::path(summary.at("scene").get<std::string>());
    run.parameters = readParameters(summary, directory / "summary.json");
    run.estimator = summary.value("estimator", std::string());
    run.referenceN = summary.value("reference_n", 0);
    run.device = summary.value("device", std::string());
    if (summary.contains("timing")) {
      const nlohmann::json& timing = summary["timing"];
      run.loadSeconds = timing.value("load_s", 0.0);
      run.setupSeconds = timing.value("setup_s", 0.0);
      run.totalSeconds = timing.value("total_s", 0.0);
    }
    if (summary.contains("interreflection")) run.interreflection = readInterreflection(summary);
    for (const nlohmann::json& entry : summary.at("grids")) {
      run.grids.push_back(readGrid(entry, directory));
    }
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(
        fmt::format("{}: {}", (directory / "summary.json").string(), e.what()));
  }
  return run;
}

}  // namespace penumbra
