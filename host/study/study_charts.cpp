#include "study/study_charts.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <fmt/format.h>

#include "output/result_files.hpp"
#include "study/parameter_label.hpp"
#include "study/results_table.hpp"

namespace penumbra {
namespace {

double valueOf(const CaseRecord& record, const std::string& name) {
  for (const ParameterValue& p : record.values) {
    if (p.name == name) return p.value;
  }
  return std::nan("");
}

std::vector<std::string> variedParameters(const StudyLayout& layout,
                                          const std::vector<CaseRecord>& records) {
  std::vector<std::string> varied;
  for (const std::string& name : layout.parameters) {
    std::set<double> values;
    for (const CaseRecord& r : records) values.insert(valueOf(r, name));
    if (values.size() > 1) varied.push_back(name);
  }
  return varied;
}

// The legend of a series: the values of the other varied parameters.
std::string seriesName(const CaseRecord& record, const std::vector<std::string>& others) {
  ParameterValues values;
  for (const std::string& name : others) values.push_back({name, valueOf(record, name)});
  return describeParameters(values);
}

std::string metricLabel(StudyMetric metric) {
  const StudyMetricInfo& info = metricInfo(metric);
  return info.unit.empty() ? std::string(info.name) : fmt::format("{} [{}]", info.name, info.unit);
}

LineChart chartOf(const StudyLayout& layout, const std::vector<CaseRecord>& records,
                  const std::string& grid, StudyMetric metric, const std::string& x,
                  const std::vector<std::string>& varied) {
  LineChart chart;
  chart.xLabel = parameterLabel(x);  // "window width [m]", not the column name window_width_m
  chart.yLabel = metricLabel(metric);
  chart.title =
      chart.yLabel + (layout.grids.size() > 1 ? " on " + grid : "") + " vs " + chart.xLabel;
  std::vector<std::string> others;
  if (layout.combination == Combination::Grid) {
    for (const std::string& name : varied) {
      if (name != x) others.push_back(name);
    }
  }
  // Series in the order their first case comes; points sorted by x afterwards.
  std::vector<std::string> order;
  std::map<std::string, std::vector<std::pair<double, double>>> points;
  for (const CaseRecord& r : records) {
    const std::string name =
        others.empty() ? metricColumn(layout, metric, grid) : seriesName(r, others);
    if (!points.count(name)) order.push_back(name);
    auto& series = points[name];
    for (const CaseGridResult& g : r.grids) {
      const double y = metricValue(g, metric);
      if (g.name == grid && std::isfinite(y)) series.emplace_back(valueOf(r, x), y);
    }
  }
  for (const std::string& name : order) {
    auto& xy = points[name];
    std::sort(xy.begin(), xy.end());
    ChartSeries series;
    series.name = name;
    for (const auto& [px, py] : xy) {
      series.x.push_back(px);
      series.y.push_back(py);
    }
    chart.series.push_back(std::move(series));
  }
  return chart;
}

}  // namespace

std::vector<ChartFile> studyCharts(const StudyLayout& layout,
                                   const std::vector<CaseRecord>& records) {
  const std::vector<std::string> varied = variedParameters(layout, records);
  std::vector<ChartFile> charts;
  for (const std::string& grid : layout.grids) {
    for (StudyMetric metric : layout.metrics) {
      for (const std::string& x : varied) {
        const std::string stem = gridFileStem(metricColumn(layout, metric, grid) + "-vs-" + x);
        LineChart chart = chartOf(layout, records, grid, metric, x, varied);
        // A metric undefined in every case (a point list's U0) has nothing to draw.
        const bool empty = std::all_of(chart.series.begin(), chart.series.end(),
                                       [](const ChartSeries& s) { return s.x.empty(); });
        if (!empty) charts.push_back(ChartFile{std::move(chart), stem + ".png"});
      }
    }
  }
  return charts;
}

}  // namespace penumbra
