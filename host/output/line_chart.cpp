#include "output/line_chart.hpp"

namespace penumbra {

std::vector<std::size_t> firstIdenticalSeries(const LineChart& chart) {
  std::vector<std::size_t> first(chart.series.size());
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    first[i] = i;
    for (std::size_t j = 0; j < i; ++j) {
      // Exact: the values are the metrics as the cases' files hold them, and equal digits are
      // what would draw one line over the other.
      if (chart.series[j].x == chart.series[i].x && chart.series[j].y == chart.series[i].y) {
        first[i] = j;
        break;
      }
    }
  }
  return first;
}

std::vector<std::string> chartLegendLabels(const LineChart& chart) {
  const std::vector<std::size_t> first = firstIdenticalSeries(chart);
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    labels.push_back(first[i] == i
                         ? chart.series[i].name
                         : chart.series[i].name + " (= " + chart.series[first[i]].name + ")");
  }
  return labels;
}

}  // namespace penumbra
