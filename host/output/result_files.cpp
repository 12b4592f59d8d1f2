#include "output/result_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <set>
#include <stdexcept>

#include "output/grid_rows.hpp"
#include "output/json_number.hpp"
#include "output/staged_directory.hpp"

namespace penumbra {

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

void writeFile(const std::filesystem::path& path, const std::function<void(std::ostream&)>& body) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot create " + path.string());
  body(out);
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

nlohmann::json parameterJson(const ParameterValues& values) {
  nlohmann::json object = nlohmann::json::object();
  for (const ParameterValue& p : values) object[p.name] = p.value;
  return object;
}

std::string gridFileStem(const std::string& gridName) {
  return safeFileStem(gridName, "grid_");
}

std::string safeFileStem(const std::string& name, const std::string& prefix) {
  std::string stem;
  for (char c : name) {
    const bool plain = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') ||
                       c == '.' || c == '_' || c == '-';
    stem += plain ? c : '_';
  }
  // "" and names starting with '.' would be hidden or special ("..").
  if (stem.empty() || stem.front() == '.') stem.insert(0, prefix);
  return stem;
}

std::string gridKindName(GridKind kind) {
  switch (kind) {
    case GridKind::WorkPlane:
      return "work-plane";
    case GridKind::Rect:
      return "rect";
    case GridKind::Points:
      return "points";
  }
  throw std::logic_error("unknown GridKind");
}

GridKind gridKindFromName(const std::string& name) {
  for (GridKind kind : {GridKind::WorkPlane, GridKind::Rect, GridKind::Points}) {
    if (gridKindName(kind) == name) return kind;
  }
  throw std::runtime_error("unknown grid kind '" + name +
                           "' (expected work-plane, rect or points)");
}

std::vector<std::string> resultFileNames(const RunReport& report) {
  std::vector<std::string> gridNames;
  for (const GridReport& grid : report.grids) gridNames.push_back(grid.name);
  return resultFileNames(gridNames);
}

std::vector<std::string> resultFileNames(const std::vector<std::string>& gridNames) {
  std::vector<std::string> names;
  std::set<std::string> stems;
  for (const std::string& name : gridNames) {
    const std::string stem = gridFileStem(name);
    if (!stems.insert(stem).second) {
      throw std::runtime_error(fmt::format(
          "grid '{}' would be written to {}.csv, which another grid uses; rename one of them", name,
          stem));
    }
    names.push_back(stem + ".csv");
    names.push_back(stem + ".res");
    names.push_back(stem + ".pts");
  }
  names.push_back("summary.json");
  return names;
}

NumberDigits illuminanceDigits(const RunReport& report) {
  return report.estimator == "reference" ? NumberDigits::Double : NumberDigits::Float;
}

void writeGridCsv(std::ostream& out, const GridReport& grid, NumberDigits digits) {
  const bool withParts = !grid.direct.empty();
  const bool withSun = grid.sunMetrics.has_value();
  const std::string header = gridCsvHeader(withParts, grid.daylight.has_value(), withSun);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  GridRows rows(digits);
  if (grid.daylight) rows.setOutdoorIlluminance(grid.daylight->outdoorIlluminance);
  rows.setSunColumn(withSun);
  for (std::size_t i = 0; i < grid.points.size(); ++i) {
    const GridRowValues values{
        grid.illuminance[i],
        withParts ? &grid.direct[i] : nullptr,
        i < grid.sun.size() ? grid.sun[i] : 0.0,
        i < grid.sunReflected.size() ? grid.sunReflected[i] : 0.0,
        i < grid.skyComponent.size() ? &grid.skyComponent[i] : nullptr,
        i < grid.externalComponent.size() ? &grid.externalComponent[i] : nullptr};
    rows.add(grid.points[i].position, grid.points[i].normal, values,
             csvField(grid.insideSolids[i]));
    if (rows.csv().size() > (1u << 20)) {
      out.write(rows.csv().data(), static_cast<std::streamsize>(rows.csv().size()));
      rows.clear();
    }
  }
  out.write(rows.csv().data(), static_cast<std::streamsize>(rows.csv().size()));
}

void writeGridPts(std::ostream& out, const GridReport& grid) {
  GridRows rows(NumberDigits::Double);  // E is not written
  for (const SamplePoint& point : grid.points) {
    rows.addPoint(point.position, point.normal);
    if (rows.pts().size() > (1u << 20)) {
      out.write(rows.pts().data(), static_cast<std::streamsize>(rows.pts().size()));
      rows.clear();
    }
  }
  out.write(rows.pts().data(), static_cast<std::streamsize>(rows.pts().size()));
}

void writeGridRes(std::ostream& out, const GridReport& grid, NumberDigits digits) {
  GridRows rows(digits);
  for (std::size_t i = 0; i < grid.illuminance.size(); ++i) {
    rows.addIlluminance(grid.illuminance[i]);
    if (rows.res().size() > (1u << 20)) {
      out.write(rows.res().data(), static_cast<std::streamsize>(rows.res().size()));
      rows.clear();
    }
  }
  out.write(rows.res().data(), static_cast<std::streamsize>(rows.res().size()));
}

std::string maintenanceMeaning(const std::vector<LuminaireReport>& luminaires) {
  const bool maintained =
      std::any_of(luminaires.begin(), luminaires.end(),
                  [](const LuminaireReport& l) { return l.maintenanceFactor != 1.0; });
  if (!maintained) return "";
  const bool shared =
      std::all_of(luminaires.begin(), luminaires.end(), [&](const LuminaireReport& l) {
        return l.maintenanceFactor == luminaires.front().maintenanceFactor;
      });
  if (shared) return fmt::format("maintained, MF {}", luminaires.front().maintenanceFactor);
  std::string each;
  for (const LuminaireReport& l : luminaires)
    each += fmt::format("{}{} {}", each.empty() ? "" : ", ", l.name, l.maintenanceFactor);
  return "maintained (MF per luminaire: " + each + ")";
}

std::string illuminanceMeaning(bool interreflection,
                               const std::vector<LuminaireReport>& luminaires) {
  const std::string maintenance = maintenanceMeaning(luminaires);
  return std::string(interreflection ? "total (direct + interreflected)" : "direct only") +
         (maintenance.empty() ? "" : ", " + maintenance);
}

std::string illuminanceMeaning(const RunReport& report) {
  return illuminanceMeaning(report.interreflection.has_value(), report.luminaires);
}

nlohmann::json interreflectionJson(const InterreflectionReport& r) {
  nlohmann::json black = nlohmann::json::array();
  for (const std::string& name : r.blackSolids) black.push_back(name);
  return {
      {"elements", r.elements},
      {"element_size_m", r.elementSize},
      {"quadrature_nodes", r.nodes},
      {"surface_area_m2", r.surfaceArea},
      {"relative_residual", r.residual},
      {"transfer_reused", r.transferReused},
      {"refinement_capped", r.refinementCapped},
      {"transfer", r.linkError > 0.0 ? "hierarchical links" : "dense"},
      {"final_gather", r.linearGather ? "linear within elements" : "uniform elements"},
      {"link_error", r.linkError},
      {"links", r.links},
      {"dense_elements_past_limit", r.denseElements},
      {"solids_without_material", black},
      {"timing",
       {{"mesh_s", r.meshSeconds}, {"transfer_s", r.transferSeconds}, {"solve_s", r.solveSeconds}}},
  };
}

nlohmann::json luminairesJson(const std::vector<LuminaireReport>& reports) {
  nlohmann::json luminaires = nlohmann::json::array();
  for (const LuminaireReport& l : reports) {
    nlohmann::json entry = {{"name", l.name},
                            {"file", l.file},
                            {"format", l.format},
                            {"instances", l.instances},
                            {"lamp_lumens_lm", jsonNumber(l.lampLumens)},
                            {"zonal_flux_lm", jsonNumber(l.zonalFluxLm)},
                            {"maintenance_factor", jsonNumber(l.maintenanceFactor)},
                            {"model", l.model}};
    if (l.fitOrder >= 0) {
      // The area model: the luminance fit's order and error (relative to the peak candela), and
      // the opening's cells along its length and width ([1, 1]: the fit integrated exactly).
      entry["fit_order"] = l.fitOrder;
      entry["fit_error"] = jsonNumber(l.fitError);
      entry["parts"] = {l.partsAlongLength, l.partsAlongWidth};
    }
    luminaires.push_back(std::move(entry));
  }
  return luminaires;
}

namespace {

nlohmann::json metricsJson(const GridMetrics& metrics, GridKind kind, NumberDigits digits) {
  const GridMetrics m = reportedMetrics(metrics, kind, digits);
  return {{"Eavg_lx", jsonNumber(m.eAvg)},
          {"Emin_lx", jsonNumber(m.eMin)},
          {"Emax_lx", jsonNumber(m.eMax)},
          {"U0", jsonNumber(m.u0)},
          {"Ud", jsonNumber(m.ud)}};
}

}  // namespace

GridMetrics reportedMetrics(const GridMetrics& metrics, GridKind kind, NumberDigits digits) {
  GridMetrics m = metrics;
  for (double* value : {&m.eAvg, &m.eMin, &m.eMax, &m.u0, &m.ud})
    *value = withDigits(*value, digits);
  if (kind == GridKind::Points) m.u0 = m.ud = std::numeric_limits<double>::quiet_NaN();
  return m;
}

// The EN 17037 daylight provision of a grid (grid_metrics.hpp): targets and shares in %.
nlohmann::json provisionJson(const DaylightProvision& p) {
  nlohmann::json levels = nlohmann::json::array();
  for (std::size_t k = 0; k < p.levels.size(); ++k) {
    const DaylightProvisionLevel& level = kDaylightProvisionLevels[k];
    const DaylightProvisionCheck& c = p.levels[k];
    levels.push_back(
        {{"level", level.name},
         {"target_illuminance_lx", level.targetIlluminance},
         {"minimum_target_illuminance_lx", level.minimumTargetIlluminance},
         {"DF_target_pct", jsonNumber(c.target)},
         {"DF_minimum_target_pct", jsonNumber(c.minimumTarget)},
         {"share_at_least_target_pct", jsonNumber(100.0 * c.shareTarget)},
         {"share_at_least_minimum_target_pct", jsonNumber(100.0 * c.shareMinimumTarget)},
         {"met", c.met}});
  }
  return {{"median_diffuse_illuminance_lx", p.medianDiffuseIlluminance},
          {"required_share_target_pct", 100.0 * kTargetShare},
          {"required_share_minimum_target_pct", 100.0 * kMinimumTargetShare},
          {"level_reached", p.reached()},
          {"levels", levels}};
}

// A component's mean (%) when the components are known, else null (a direct-only run).
nlohmann::json optionalJson(const std::optional<DaylightComponents>& components,
                            double DaylightComponents::*member) {
  return components ? jsonNumber((*components).*member) : nlohmann::json(nullptr);
}

// The daylight factor figures of a grid (grid_metrics.hpp), in %.
nlohmann::json daylightJson(const DaylightMetrics& m) {
  nlohmann::json shares = nlohmann::json::array();
  for (std::size_t k = 0; k < m.shareAtLeast.size(); ++k)
    shares.push_back({{"DF_target_pct", kDaylightFactorTargets[k]},
                      {"share_at_least_pct", jsonNumber(100.0 * m.shareAtLeast[k])}});
  nlohmann::json result = {
      {"outdoor_horizontal_illuminance_lx", m.outdoorIlluminance},
      {"DFavg_pct", jsonNumber(m.mean)},
      {"DFmedian_pct", jsonNumber(m.median)},
      {"DFmin_pct", jsonNumber(m.min)},
      {"DFmax_pct", jsonNumber(m.max)},
      {"DF_uniformity", jsonNumber(m.uniformity)},
      {"DFavg_direct_pct", jsonNumber(m.directMean)},
      {"DFavg_internal_pct", jsonNumber(m.internalMean)},
      {"SCavg_pct", optionalJson(m.components, &DaylightComponents::sky)},
      {"ERCavg_pct", optionalJson(m.components, &DaylightComponents::externallyReflected)},
      {"IRCavg_pct", optionalJson(m.components, &DaylightComponents::internallyReflected)},
      {"shares", shares}};
  if (m.provision) result["en17037"] = provisionJson(*m.provision);
  // EN 17037's reference plane is horizontal: a grid that does not face up gets no verdict.
  result["faces_up"] = m.horizontal;
  return result;
}

nlohmann::json summaryJson(const RunReport& report) {
  const NumberDigits digits = illuminanceDigits(report);
  nlohmann::json grids = nlohmann::json::array();
  for (const GridReport& grid : report.grids) {
    const GridMetrics& m = grid.metrics;
    const std::string stem = gridFileStem(grid.name);
    nlohmann::json entry({
        {"name", grid.name},
        {"csv", stem + ".csv"},
        {"res", stem + ".res"},
        {"pts", stem + ".pts"},
        {"kind", gridKindName(grid.kind)},
        {"columns",
         grid.kind == GridKind::Points ? nlohmann::json(nullptr) : nlohmann::json(grid.columns)},
        {"rows",
         grid.kind == GridKind::Points ? nlohmann::json(nullptr) : nlohmann::json(grid.rows)},
        {"points", m.points},
        {"points_inside_solids", m.pointsInsideSolids},
        {"spacing_m", m.spacing > 0.0 ? jsonNumber(m.spacing) : nlohmann::json(nullptr)},
        {"time_s", grid.seconds},
    });
    entry.update(metricsJson(m, grid.kind, digits));
    if (grid.directMetrics) entry["direct"] = metricsJson(*grid.directMetrics, grid.kind, digits);
    if (grid.daylight) entry["daylight_factor"] = daylightJson(*grid.daylight);
    if (grid.sunMetrics)
      entry["sun"] = {{"Esun_avg_lx", jsonNumber(withDigits(grid.sunMetrics->eAvg, digits))},
                      {"Esun_max_lx", jsonNumber(withDigits(grid.sunMetrics->eMax, digits))},
                      {"sunlit_share_pct", jsonNumber(100.0 * grid.sunMetrics->sunlitShare)}};
    grids.push_back(std::move(entry));
  }
  nlohmann::json summary = {
      {"penumbra_version", report.version},
      {"scene", report.sceneFile.string()},
      // `penumbra plot` reads the scene again, from wherever it is started.
      {"scene_absolute",
       report.sceneFile.empty()
           ? nlohmann::json(nullptr)
           : nlohmann::json(
                 std::filesystem::absolute(report.sceneFile).lexically_normal().string())},
      {"parameters", parameterJson(report.parameters)},
      {"estimator", report.estimator},
      {"device", report.device},
      {"timing",
       {{"load_s", report.loadSeconds},
        {"setup_s", report.setupSeconds},
        {"total_s", report.totalSeconds}}},
      {"warnings", report.warnings},
      {"grids", grids},
  };
  if (report.estimator == "reference") summary["reference_n"] = report.referenceN;
  summary["illuminance"] = illuminanceMeaning(report);
  if (report.interreflection)
    summary["interreflection"] = interreflectionJson(*report.interreflection);
  if (!report.luminaires.empty()) summary["luminaires"] = luminairesJson(report.luminaires);
  if (report.sky) {
    const SkyReport& sky = *report.sky;
    const bool patches = sky.patches > 0;
    // The type, subdivision and patch count of a cie-general sky; null for the exact skies.
    const auto patchField = [&](int value) {
      return patches ? nlohmann::json(value) : nlohmann::json(nullptr);
    };
    summary["sky"] = {{"model", sky.model},
                      {"horizontal_illuminance_lx", jsonNumber(sky.horizontalIlluminance)},
                      {"ground_reflectance", jsonNumber(sky.groundReflectance)},
                      {"cie_type", patchField(sky.cieType)},
                      {"subdivision", patchField(sky.subdivision)},
                      {"patches", patchField(sky.patches)}};
  }
  if (report.sun)
    summary["sun"] = {{"azimuth_deg", report.sun->azimuthDegrees},
                      {"elevation_deg", report.sun->elevationDegrees},
                      {"direct_normal_illuminance_lx", report.sun->directNormalIlluminance},
                      {"above_horizon", report.sun->aboveHorizon}};
  return summary;
}

void writeResultFiles(const RunReport& report, const std::filesystem::path& directory) {
  resultFileNames(report);  // refuses clashing names before anything is created
  const NumberDigits digits = illuminanceDigits(report);
  for (const GridReport& grid : report.grids) {
    const std::string stem = gridFileStem(grid.name);
    writeFile(directory / (stem + ".csv"),
              [&](std::ostream& out) { writeGridCsv(out, grid, digits); });
    writeFile(directory / (stem + ".res"),
              [&](std::ostream& out) { writeGridRes(out, grid, digits); });
    writeFile(directory / (stem + ".pts"), [&](std::ostream& out) { writeGridPts(out, grid); });
  }
  writeSummaryFile(report, directory);
}

void writeSummaryFile(const RunReport& report, const std::filesystem::path& directory) {
  writeFile(directory / "summary.json",
            [&](std::ostream& out) { out << summaryJson(report).dump(2) << "\n"; });
}

void writeResults(const RunReport& report, const std::filesystem::path& directory) {
  resultFileNames(report);  // refuses clashing names before anything is created
  StagedDirectory staged(directory);
  writeResultFiles(report, staged.staging());
  staged.commit();
}

}  // namespace penumbra
