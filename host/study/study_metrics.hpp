#pragma once
// The grid metrics a study can tabulate and chart, with their names, units and table columns.
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grid/grid_metrics.hpp"
#include "output/number_text.hpp"

namespace penumbra {

// The daylight metrics (DF*, EN17037) are defined for scenes with a sky only, the sun's (Esun*,
// sunlit_share) for scenes with a sun only.
enum class StudyMetric {
  Eavg,
  Emin,
  Emax,
  U0,
  Ud,
  DFavg,
  DFmin,
  DFmedian,
  SCavg,
  ERCavg,
  IRCavg,
  EN17037,
  EsunAvg,
  EsunMax,
  SunlitShare
};

// What the scene needs for a metric to have a value: Components a sky and interreflection (the
// daylight factor's split into SC, ERC and IRC, grid_metrics.hpp).
enum class MetricNeeds { Nothing, Sky, Sun, Components };

struct StudyMetricInfo {
  StudyMetric metric;
  std::string_view name;    // as written in a study file: "Eavg"
  std::string_view unit;    // "lx", "%", or "" for a ratio or a level
  std::string_view column;  // the table header: "Eavg_lx", "U0" (summary.json's key too)
  MetricNeeds needs = MetricNeeds::Nothing;
};

// A case's daylight figures on one grid (grid_metrics.hpp); NaN without a sky, `level` NaN also
// without the site's median diffuse illuminance.
struct CaseDaylight {
  double mean = std::numeric_limits<double>::quiet_NaN();    // %: DFavg
  double min = std::numeric_limits<double>::quiet_NaN();     // %: DFmin
  double median = std::numeric_limits<double>::quiet_NaN();  // %: DFmedian
  // %: the mean's components SCavg, ERCavg, IRCavg; NaN without interreflection.
  double sky = std::numeric_limits<double>::quiet_NaN();
  double externallyReflected = std::numeric_limits<double>::quiet_NaN();
  double internallyReflected = std::numeric_limits<double>::quiet_NaN();
  // The EN 17037 daylight provision reached: 0 none, 1 minimum, 2 medium, 3 high.
  double level = std::numeric_limits<double>::quiet_NaN();
};
CaseDaylight caseDaylight(const DaylightMetrics& daylight);

// A case's direct sunlight on one grid (grid_metrics.hpp, SunMetrics); NaN without a sun.
struct CaseSun {
  double eAvg = std::numeric_limits<double>::quiet_NaN();         // lx: Esun_avg
  double eMax = std::numeric_limits<double>::quiet_NaN();         // lx: Esun_max
  double sunlitShare = std::numeric_limits<double>::quiet_NaN();  // % of the points with E_sun > 0
};
// `sun` with its illuminances rounded to `digits`, as summary.json writes them.
CaseSun caseSun(const SunMetrics& sun, NumberDigits digits);

// Everything a study tabulates of a case on one grid.
struct CaseGridFigures {
  GridMetrics metrics;
  CaseDaylight daylight;  // NaN without a sky
  CaseSun sun;            // NaN without a sun
};

// Every metric, in the order of the tables.
const std::vector<StudyMetricInfo>& studyMetrics();
const StudyMetricInfo& metricInfo(StudyMetric metric);
std::optional<StudyMetric> metricNamed(std::string_view name);
double metricValue(const CaseGridFigures& figures, StudyMetric metric);

}  // namespace penumbra
