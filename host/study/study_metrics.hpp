#pragma once
// The grid metrics a study can tabulate and chart, with their names, units and table columns.
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grid/grid_metrics.hpp"

namespace penumbra {

// The daylight metrics (DF*, EN17037) are defined for scenes with a sky only.
enum class StudyMetric { Eavg, Emin, Emax, U0, Ud, DFavg, DFmin, DFmedian, EN17037 };

struct StudyMetricInfo {
  StudyMetric metric;
  std::string_view name;    // as written in a study file: "Eavg"
  std::string_view unit;    // "lx", "%", or "" for a ratio or a level
  std::string_view column;  // the table header: "Eavg_lx", "U0" (summary.json's key too)
  bool daylight = false;    // needs a sky
};

// A case's daylight figures on one grid (grid_metrics.hpp); NaN without a sky, `level` NaN also
// without the site's median diffuse illuminance.
struct CaseDaylight {
  double mean = std::numeric_limits<double>::quiet_NaN();    // %: DFavg
  double min = std::numeric_limits<double>::quiet_NaN();     // %: DFmin
  double median = std::numeric_limits<double>::quiet_NaN();  // %: DFmedian
  // The EN 17037 daylight provision reached: 0 none, 1 minimum, 2 medium, 3 high.
  double level = std::numeric_limits<double>::quiet_NaN();
};
CaseDaylight caseDaylight(const DaylightMetrics& daylight);

// Every metric, in the order of the tables.
const std::vector<StudyMetricInfo>& studyMetrics();
const StudyMetricInfo& metricInfo(StudyMetric metric);
std::optional<StudyMetric> metricNamed(std::string_view name);
double metricValue(const GridMetrics& metrics, const CaseDaylight& daylight, StudyMetric metric);

}  // namespace penumbra
