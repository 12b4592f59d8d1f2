#include "study/study_metrics.hpp"

#include <algorithm>

namespace penumbra {

const std::vector<StudyMetricInfo>& studyMetrics() {
  static const std::vector<StudyMetricInfo> metrics{
      {StudyMetric::Eavg, "Eavg", "lx", "Eavg_lx"},
      {StudyMetric::Emin, "Emin", "lx", "Emin_lx"},
      {StudyMetric::Emax, "Emax", "lx", "Emax_lx"},
      {StudyMetric::U0, "U0", "", "U0"},
      {StudyMetric::Ud, "Ud", "", "Ud"},
  };
  return metrics;
}

const StudyMetricInfo& metricInfo(StudyMetric metric) {
  const auto& all = studyMetrics();
  return *std::find_if(all.begin(), all.end(),
                       [&](const StudyMetricInfo& m) { return m.metric == metric; });
}

std::optional<StudyMetric> metricNamed(std::string_view name) {
  for (const StudyMetricInfo& m : studyMetrics()) {
    if (m.name == name || m.column == name) return m.metric;
  }
  return std::nullopt;
}

double metricValue(const GridMetrics& metrics, StudyMetric metric) {
  switch (metric) {
    case StudyMetric::Eavg:
      return metrics.eAvg;
    case StudyMetric::Emin:
      return metrics.eMin;
    case StudyMetric::Emax:
      return metrics.eMax;
    case StudyMetric::U0:
      return metrics.u0;
    case StudyMetric::Ud:
      return metrics.ud;
  }
  return metrics.eAvg;
}

}  // namespace penumbra
