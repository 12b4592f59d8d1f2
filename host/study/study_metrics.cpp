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
      {StudyMetric::DFavg, "DFavg", "%", "DFavg_pct", MetricNeeds::Sky},
      {StudyMetric::DFmin, "DFmin", "%", "DFmin_pct", MetricNeeds::Sky},
      {StudyMetric::DFmedian, "DFmedian", "%", "DFmedian_pct", MetricNeeds::Sky},
      {StudyMetric::SCavg, "SCavg", "%", "SCavg_pct", MetricNeeds::Components},
      {StudyMetric::ERCavg, "ERCavg", "%", "ERCavg_pct", MetricNeeds::Components},
      {StudyMetric::IRCavg, "IRCavg", "%", "IRCavg_pct", MetricNeeds::Components},
      // 0 none, 1 minimum, 2 medium, 3 high (CaseDaylight::level).
      {StudyMetric::EN17037, "EN17037_level", "", "EN17037_level", MetricNeeds::Sky},
      {StudyMetric::EsunAvg, "Esun_avg", "lx", "Esun_avg_lx", MetricNeeds::Sun},
      {StudyMetric::EsunMax, "Esun_max", "lx", "Esun_max_lx", MetricNeeds::Sun},
      {StudyMetric::SunlitShare, "sunlit_share", "%", "sunlit_share_pct", MetricNeeds::Sun},
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

CaseDaylight caseDaylight(const DaylightMetrics& daylight) {
  CaseDaylight d;
  d.mean = daylight.mean;
  d.min = daylight.min;
  d.median = daylight.median;
  if (daylight.components) {
    d.sky = daylight.components->sky;
    d.externallyReflected = daylight.components->externallyReflected;
    d.internallyReflected = daylight.components->internallyReflected;
  }
  if (daylight.provision) {
    d.level = 0.0;
    for (std::size_t k = 0; k < daylight.provision->levels.size(); ++k)
      if (daylight.provision->levels[k].met) d.level = static_cast<double>(k + 1);
  }
  return d;
}

CaseSun caseSun(const SunMetrics& sun, NumberDigits digits) {
  return CaseSun{withDigits(sun.eAvg, digits), withDigits(sun.eMax, digits),
                 100.0 * sun.sunlitShare};
}

double metricValue(const CaseGridFigures& figures, StudyMetric metric) {
  const GridMetrics& metrics = figures.metrics;
  const CaseDaylight& daylight = figures.daylight;
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
    case StudyMetric::DFavg:
      return daylight.mean;
    case StudyMetric::DFmin:
      return daylight.min;
    case StudyMetric::DFmedian:
      return daylight.median;
    case StudyMetric::SCavg:
      return daylight.sky;
    case StudyMetric::ERCavg:
      return daylight.externallyReflected;
    case StudyMetric::IRCavg:
      return daylight.internallyReflected;
    case StudyMetric::EN17037:
      return daylight.level;
    case StudyMetric::EsunAvg:
      return figures.sun.eAvg;
    case StudyMetric::EsunMax:
      return figures.sun.eMax;
    case StudyMetric::SunlitShare:
      return figures.sun.sunlitShare;
  }
  return metrics.eAvg;
}

}  // namespace penumbra
