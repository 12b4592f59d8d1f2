#pragma once
// The grid metrics a study can tabulate and chart, with their names, units and table columns.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grid/grid_metrics.hpp"

namespace penumbra {

enum class StudyMetric { Eavg, Emin, Emax, U0, Ud };

struct StudyMetricInfo {
  StudyMetric metric;
  std::string_view name;    // as written in a study file: "Eavg"
  std::string_view unit;    // "lx", or "" for a ratio
  std::string_view column;  // the table header: "Eavg_lx", "U0" (summary.json's key too)
};

// Every metric, in the order of the tables.
const std::vector<StudyMetricInfo>& studyMetrics();
const StudyMetricInfo& metricInfo(StudyMetric metric);
std::optional<StudyMetric> metricNamed(std::string_view name);
double metricValue(const GridMetrics& metrics, StudyMetric metric);

}  // namespace penumbra
