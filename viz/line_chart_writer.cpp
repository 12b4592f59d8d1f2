#include "viz/line_chart_writer.hpp"

#include <fmt/format.h>
#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkDoubleArray.h>
#include <vtkPen.h>
#include <vtkPlotLine.h>
#include <vtkRect.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <array>
#include <stdexcept>

#include "viz/fonts.hpp"
#include "viz/render_png.hpp"

namespace penumbra::viz {

namespace {

// Okabe and Ito (2008): told apart by readers with any common colour-vision deficiency. Yellow
// last: it is faint on white.
constexpr std::array<std::array<int, 3>, 8> kOkabeIto{{
    {0, 114, 178},
    {213, 94, 0},
    {0, 158, 115},
    {230, 159, 0},
    {204, 121, 167},
    {86, 180, 233},
    {0, 0, 0},
    {240, 228, 66},
}};

vtkSmartPointer<vtkTable> seriesTable(const ChartSeries& series) {
  if (series.x.size() != series.y.size()) {
    throw std::invalid_argument(fmt::format("chart series '{}': {} x values but {} y values",
                                            series.name, series.x.size(), series.y.size()));
  }
  auto x = vtkSmartPointer<vtkDoubleArray>::New();
  x->SetName("x");
  auto y = vtkSmartPointer<vtkDoubleArray>::New();
  y->SetName(series.name.c_str());
  for (std::size_t i = 0; i < series.x.size(); ++i) {
    x->InsertNextValue(series.x[i]);
    y->InsertNextValue(series.y[i]);
  }
  auto table = vtkSmartPointer<vtkTable>::New();
  table->AddColumn(x);
  table->AddColumn(y);
  return table;
}

void styleAxis(vtkAxis* axis, const std::string& title, double f) {
  axis->SetTitle(title);
  useLabelFont(axis->GetTitleProperties(), false);
  axis->GetTitleProperties()->SetFontSize(static_cast<int>(20 * f + 0.5));
  useLabelFont(axis->GetLabelProperties(), false);
  axis->GetLabelProperties()->SetFontSize(static_cast<int>(17 * f + 0.5));
  axis->GetGridPen()->SetColor(220, 220, 220);
}

}  // namespace

Rgb chartSeriesColour(std::size_t index) {
  const auto& c = kOkabeIto[index % kOkabeIto.size()];
  return {c[0] / 255.0, c[1] / 255.0, c[2] / 255.0};
}

void writeLineChart(const LineChart& chart, const std::filesystem::path& png) {
  const double f = std::max(chart.width, 400) / 1200.0;
  auto xy = vtkSmartPointer<vtkChartXY>::New();
  xy->SetTitle(chart.title);
  useLabelFont(xy->GetTitleProperties(), true);
  xy->GetTitleProperties()->SetFontSize(static_cast<int>(24 * f + 0.5));
  styleAxis(xy->GetAxis(vtkAxis::BOTTOM), chart.xLabel, f);
  styleAxis(xy->GetAxis(vtkAxis::LEFT), chart.yLabel, f);
  xy->SetShowLegend(!chart.series.empty());
  useLabelFont(xy->GetLegend()->GetLabelProperties(), false);
  xy->GetLegend()->SetLabelSize(static_cast<int>(17 * f + 0.5));

  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    const ChartSeries& series = chart.series[i];
    vtkPlot* plot = xy->AddPlot(vtkChart::LINE);
    plot->SetInputData(seriesTable(series), 0, 1);
    plot->SetLabel(series.name);
    const auto& c = kOkabeIto[i % kOkabeIto.size()];
    plot->SetColor(static_cast<unsigned char>(c[0]), static_cast<unsigned char>(c[1]),
                   static_cast<unsigned char>(c[2]), 255);
    plot->SetWidth(static_cast<float>(3.0 * f));
    if (auto* line = vtkPlotLine::SafeDownCast(plot)) {
      line->SetMarkerStyle(vtkPlotPoints::CIRCLE);
      line->SetMarkerSize(static_cast<float>(9.0 * f));
    }
  }

  // A margin on every side: VTK lays the chart out to the window's edge, where the last tick
  // label and the outermost markers would be cut.
  xy->SetAutoSize(false);
  const float margin = static_cast<float>(24 * f);
  xy->SetSize(vtkRectf(margin, margin, static_cast<float>(chart.width) - 2 * margin,
                       static_cast<float>(chart.height) - 2 * margin));

  auto context = vtkSmartPointer<vtkContextActor>::New();
  context->GetScene()->AddItem(xy);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor(context);
  renderToPng(renderer, chart.width, chart.height, png);
}

}  // namespace penumbra::viz
