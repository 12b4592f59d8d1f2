#include "output/summary_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "output/result_files.hpp"

namespace penumbra {

namespace {

constexpr const char* kUndefined = "-";

// Illuminance to one decimal like a lighting report, but small values keep three significant
// digits (a 0.04 lx spill must not read as 0.0).
std::string lux(double e) {
  if (!std::isfinite(e)) return kUndefined;
  return std::fabs(e) >= 10.0 || e == 0.0 ? fmt::format("{:.1f}", e) : fmt::format("{:.3g}", e);
}

std::string ratio(double u) {
  return std::isfinite(u) ? fmt::format("{:.3f}", u) : kUndefined;
}

// Both distances between points of a planar grid, along u and along v: "0.5 × 0.48".
std::string spacing(const GridReport& grid) {
  if (grid.spacingU > 0.0) return fmt::format("{:.3g} × {:.3g}", grid.spacingU, grid.spacingV);
  return grid.metrics.spacing > 0.0 ? fmt::format("{:.3g}", grid.metrics.spacing) : kUndefined;
}

// The terminal columns `text` takes: its UTF-8 code points ("×" is one), as fmt pads.
std::size_t columnsOf(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

using Row = std::vector<std::string>;

// Rows as a table: the first the header, a rule under it; names left, numbers right.
std::string formatRows(const std::vector<Row>& rows) {
  std::vector<std::size_t> width(rows.front().size(), 0);
  for (const Row& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], columnsOf(row[c]));
  }
  std::string table;
  const auto appendRow = [&](const Row& row) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c > 0) table += " | ";
      table += c == 0 ? fmt::format("{:<{}}", row[c], width[c])
                      : fmt::format("{:>{}}", row[c], width[c]);
    }
    table += '\n';
  };
  appendRow(rows.front());
  for (std::size_t c = 0; c < width.size(); ++c) {
    if (c > 0) table += "-|-";
    table += std::string(width[c], '-');
  }
  table += '\n';
  for (std::size_t r = 1; r < rows.size(); ++r) appendRow(rows[r]);
  return table;
}

std::string percent(double df) {
  return std::isfinite(df) ? fmt::format("{:.2f}", df) : kUndefined;
}

// The EN 17037 daylight provision of each grid with a sky (grid_metrics.hpp, DaylightProvision):
// per level its DF targets, the shares of the plane that reach them and the verdict.
std::string provisionTable(const RunReport& report) {
  std::vector<Row> rows;
  double median = 0.0;
  bool withoutSite = false;
  std::string notHorizontal;
  for (const GridReport& grid : report.grids) {
    if (!grid.daylight) continue;
    if (!grid.daylight->horizontal) {
      notHorizontal += fmt::format(
          "{}: no EN 17037 verdict: the grid does not face up (the standard's reference plane is "
          "horizontal)\n",
          grid.name);
      continue;
    }
    if (!grid.daylight->provision) {
      withoutSite = true;
      continue;
    }
    const DaylightProvision& p = *grid.daylight->provision;
    median = p.medianDiffuseIlluminance;
    if (rows.empty())
      rows.push_back({"Grid", "Level", "E_T [lx]", "D_T [%]", "DF >= D_T [% of points]",
                      "E_TM [lx]", "D_TM [%]", "DF >= D_TM [% of points]", "Met"});
    for (std::size_t k = 0; k < p.levels.size(); ++k) {
      const DaylightProvisionLevel& level = kDaylightProvisionLevels[k];
      const DaylightProvisionCheck& c = p.levels[k];
      rows.push_back({grid.name, std::string(level.name),
                      fmt::format("{:g}", level.targetIlluminance), percent(c.target),
                      percent(100.0 * c.shareTarget),
                      fmt::format("{:g}", level.minimumTargetIlluminance), percent(c.minimumTarget),
                      percent(100.0 * c.shareMinimumTarget), c.met ? "yes" : "no"});
    }
  }
  std::string table;
  if (!rows.empty()) {
    table = fmt::format(
        "EN 17037 daylight provision (daylight factor method, the grid as reference plane, "
        "E_v,d,med = {:g} lx): a level is met when DF >= D_T = 100 · E_T / E_v,d,med on >= "
        "{:g} % of the points and DF >= D_TM = 100 · E_TM / E_v,d,med on >= {:g} %\n",
        median, 100.0 * kTargetShare, 100.0 * kMinimumTargetShare);
    table += formatRows(rows);
    for (const GridReport& grid : report.grids)
      if (grid.daylight && grid.daylight->provision)
        table += fmt::format("{}: EN 17037 daylight provision reached: {}\n", grid.name,
                             grid.daylight->provision->reached());
  }
  if (withoutSite)
    table +=
        "EN 17037: no verdict without the site's median external diffuse illuminance "
        "(site: median_diffuse_illuminance_lx, lx)\n";
  return table + notHorizontal;
}

// The scene's sun and, per grid, the direct sunlight on it; empty without a sun.
std::string sunTable(const RunReport& report) {
  if (!report.sun) return {};
  const SunReport& sun = *report.sun;
  std::string table = fmt::format(
      "Sun: azimuth {:.2f}° (from north towards east), elevation {:.2f}°, E_dn {:g} lx\n",
      sun.azimuthDegrees, sun.elevationDegrees, sun.directNormalIlluminance);
  if (!sun.aboveHorizon) {
    table += "Sun: below the horizon: no direct sunlight (E_sun = 0)\n";
    return table;
  }
  std::vector<Row> rows;
  rows.push_back({"Grid", "Esun avg [lx]", "Esun max [lx]", "sunlit [% of points]"});
  for (const GridReport& grid : report.grids) {
    if (!grid.sunMetrics) continue;
    const SunMetrics& m = *grid.sunMetrics;
    rows.push_back({grid.name, lux(m.eAvg), lux(m.eMax), percent(100.0 * m.sunlitShare)});
  }
  return table + formatRows(rows);
}

// The daylight factor of each grid with a sky (grid_metrics.hpp); empty when none has one.
std::string daylightTable(const RunReport& report) {
  std::vector<Row> rows;
  double outdoor = 0.0;
  for (const GridReport& grid : report.grids) {
    if (!grid.daylight) continue;
    const DaylightMetrics& d = *grid.daylight;
    outdoor = d.outdoorIlluminance;
    if (rows.empty()) {
      rows.push_back({"Grid", "DFavg [%]", "DFmedian [%]", "DFmin [%]", "DFmin/DFavg"});
      for (double target : kDaylightFactorTargets)
        rows.back().push_back(fmt::format("DF >= {:g} % [% of points]", target));
      if (report.interreflection)
        for (const char* component : {"SCavg [%]", "ERCavg [%]", "IRCavg [%]"})
          rows.back().push_back(component);
    }
    rows.push_back(
        {grid.name, percent(d.mean), percent(d.median), percent(d.min), ratio(d.uniformity)});
    for (double share : d.shareAtLeast) rows.back().push_back(percent(100.0 * share));
    if (report.interreflection) {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      const DaylightComponents c = d.components.value_or(DaylightComponents{nan, nan, nan});
      for (double component : {c.sky, c.externallyReflected, c.internallyReflected})
        rows.back().push_back(percent(component));
    }
  }
  if (rows.empty()) return {};
  return fmt::format(
             "DF: daylight factor, 100 · E / {:g} lx (the sky's unobstructed horizontal "
             "illuminance; E without the sun){}\n",
             outdoor,
             report.interreflection
                 ? "; DF = SC + ERC + IRC: the sky component (the sky through the openings), "
                   "the externally reflected (the ground through them, the obstructions' faces) "
                   "and the internally reflected"
                 : "") +
         formatRows(rows) + provisionTable(report);
}

}  // namespace

std::string summaryTable(const RunReport& report) {
  std::string luminaires;
  for (const LuminaireReport& l : report.luminaires) {
    luminaires += fmt::format(
        "{}{} × {} ({:.0f} lm, MF {:.2f}, {})", luminaires.empty() ? "" : "; ", l.instances, l.name,
        l.lampLumens > 0.0 ? l.lampLumens : l.zonalFluxLm, l.maintenanceFactor, l.model);
  }
  // With interreflection, a last column gives the direct part of Eavg.
  const bool withDirect = report.interreflection.has_value();
  std::vector<Row> rows;
  rows.push_back(
      {"Grid", "Points", "Spacing [m]", "Eavg [lx]", "Emin [lx]", "Emax [lx]", "U0", "Ud"});
  if (withDirect) rows.back().push_back("Eavg direct [lx]");
  for (const GridReport& grid : report.grids) {
    const GridMetrics& m = grid.metrics;
    // Uniformity is a property of an area; scattered sensors have none.
    const bool area = grid.kind != GridKind::Points;
    rows.push_back({grid.name, fmt::format("{}", m.points), spacing(grid), lux(m.eAvg), lux(m.eMin),
                    lux(m.eMax), area ? ratio(m.u0) : kUndefined, area ? ratio(m.ud) : kUndefined});
    if (withDirect) {
      rows.back().push_back(grid.directMetrics ? lux(grid.directMetrics->eAvg) : kUndefined);
    }
  }
  const std::string maintenance = maintenanceMeaning(report.luminaires);
  std::string table =
      fmt::format("E: {}{}{}\n",
                  report.interreflection ? "total illuminance (direct + interreflected)"
                                         : "direct illuminance only",
                  !report.sun              ? ""
                  : report.interreflection ? ", with the sun's light, direct and reflected"
                                           : ", with the sun's direct light",
                  maintenance.empty() ? "" : ", " + maintenance);
  if (!luminaires.empty()) table += "Luminaires: " + luminaires + "\n";
  table += formatRows(rows);
  table += sunTable(report);
  table += daylightTable(report);
  for (const GridReport& grid : report.grids) {
    if (grid.metrics.pointsInsideSolids > 0) {
      table +=
          fmt::format("{}: {} of {} points lie inside solids (E = 0, left out of the statistics)\n",
                      grid.name, grid.metrics.pointsInsideSolids, grid.metrics.points);
    }
  }
  return table;
}

}  // namespace penumbra
