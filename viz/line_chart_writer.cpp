#include "viz/line_chart_writer.hpp"

#include <fmt/format.h>
#include <vtkAxis.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkDoubleArray.h>
#include <vtkPen.h>
#include <vtkPlotLine.h>
#include <vtkPlotPoints.h>
#include <vtkRect.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "viz/fonts.hpp"
#include "viz/overlay.hpp"
#include "viz/render_png.hpp"

namespace penumbra::viz {

namespace {

using V2 = Eigen::Vector2d;

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

// The marker of series `index`: no two of the first five alike, so that series of one colour in
// grey print, or lying on each other, stay apart.
constexpr std::array<int, 5> kMarkers{vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE,
                                      vtkPlotPoints::DIAMOND, vtkPlotPoints::CROSS,
                                      vtkPlotPoints::PLUS};

// The marker's outline in px around `c` (size: VTK's marker size), for the legend.
std::vector<V2> markerShape(int marker, const V2& c, double size) {
  const double r = size / 2;
  switch (marker) {
    case vtkPlotPoints::SQUARE:
      return {{c.x() - r, c.y() - r},
              {c.x() + r, c.y() - r},
              {c.x() + r, c.y() + r},
              {c.x() - r, c.y() + r}};
    case vtkPlotPoints::DIAMOND:
      return {{c.x(), c.y() - r}, {c.x() + r, c.y()}, {c.x(), c.y() + r}, {c.x() - r, c.y()}};
    default:
      return circle(c, r, 24);
  }
}

void addLegendMarker(vtkRenderer* renderer, int marker, const V2& c, double size, const Rgb& colour,
                     double width) {
  const double r = size / 2;
  if (marker == vtkPlotPoints::CROSS || marker == vtkPlotPoints::PLUS) {
    const double d = marker == vtkPlotPoints::CROSS ? r * 0.7071 : r;
    const std::array<std::pair<V2, V2>, 2> arms =
        marker == vtkPlotPoints::CROSS
            ? std::array<std::pair<V2, V2>, 2>{{{c + V2(-d, -d), c + V2(d, d)},
                                                {c + V2(-d, d), c + V2(d, -d)}}}
            : std::array<std::pair<V2, V2>, 2>{
                  {{c + V2(-d, 0), c + V2(d, 0)}, {c + V2(0, -d), c + V2(0, d)}}};
    for (const auto& arm : arms)
      renderer->AddActor2D(lineAt({arm.first, arm.second}, false, colour, width));
    return;
  }
  renderer->AddActor2D(fillAt(markerShape(marker, c, size), colour));
}

// How each series is drawn: identical series (firstIdenticalSeries) wider and with larger markers
// under the later ones, so that each shows round the next.
struct SeriesLook {
  Rgb colour;
  int marker = vtkPlotPoints::CIRCLE;
  double width = 3.0;       // px at 1200 px
  double markerSize = 9.0;  // px at 1200 px
};

std::vector<SeriesLook> seriesLooks(const LineChart& chart) {
  const std::vector<std::size_t> first = firstIdenticalSeries(chart);
  std::vector<SeriesLook> looks;
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    std::size_t later = 0;  // identical series after this one
    for (std::size_t j = i + 1; j < chart.series.size(); ++j) later += first[j] == first[i];
    looks.push_back({chartSeriesColour(i), kMarkers[i % kMarkers.size()],
                     3.0 + 2.5 * static_cast<double>(later),
                     9.0 + 6.0 * static_cast<double>(later)});
  }
  return looks;
}

V2 textSize(const std::string& text, int fontSize) {
  auto property = vtkSmartPointer<vtkTextProperty>::New();
  useLabelFont(property, false);
  property->SetFontSize(fontSize);
  int box[4] = {0, 0, 0, 0};
  if (!vtkTextRenderer::GetInstance()->GetBoundingBox(property, text, box, 72)) {
    return {0.6 * fontSize * static_cast<double>(text.size()), 1.2 * fontSize};
  }
  return {static_cast<double>(box[1] - box[0]), static_cast<double>(box[3] - box[2])};
}

// The legend's size and lines.
struct LegendLayout {
  std::vector<std::string> labels;
  int fontSize = 17;
  double swatch = 40, gap = 10, pad = 12, line = 28;  // px
  V2 size{0, 0};
};

LegendLayout legendLayout(const LineChart& chart, double f) {
  LegendLayout l;
  l.labels = chartLegendLabels(chart);
  l.fontSize = static_cast<int>(17 * f + 0.5);
  l.swatch *= f;
  l.gap *= f;
  l.pad *= f;
  l.line *= f;
  double widest = 0;
  for (const std::string& label : l.labels)
    widest = std::max(widest, textSize(label, l.fontSize).x());
  l.size = {2 * l.pad + l.swatch + l.gap + widest,
            2 * l.pad + l.line * static_cast<double>(l.labels.size())};
  return l;
}

void addLegend(vtkRenderer* renderer, const LegendLayout& l, const std::vector<SeriesLook>& looks,
               const PixelBox& box, double f) {
  const std::vector<V2> frame{box.lo, {box.hi.x(), box.lo.y()}, box.hi, {box.lo.x(), box.hi.y()}};
  renderer->AddActor2D(lineAt(frame, true, {0.75, 0.75, 0.75}, 1.0 * f));
  TextStyle text;
  text.size = l.fontSize;
  text.vertical = Align::Centre;
  for (std::size_t i = 0; i < l.labels.size(); ++i) {
    const double y = box.hi.y() - l.pad - l.line * (static_cast<double>(i) + 0.5);
    const double x = box.lo.x() + l.pad;
    const SeriesLook& look = looks[i];
    renderer->AddActor2D(lineAt({{x, y}, {x + l.swatch, y}}, false, look.colour, look.width * f));
    addLegendMarker(renderer, look.marker, {x + l.swatch / 2, y}, look.markerSize * f, look.colour,
                    2.0 * f);
    renderer->AddActor2D(textAt(l.labels[i], {x + l.swatch + l.gap, y}, text));
  }
}

// The pixel of `value` on `axis` (after rendering: its end points and range are set).
double axisPixel(vtkAxis* axis, double value, bool vertical) {
  const float* p1 = axis->GetPoint1();
  const float* p2 = axis->GetPoint2();
  const double a = vertical ? p1[1] : p1[0], b = vertical ? p2[1] : p2[0];
  const double lo = axis->GetMinimum(), hi = axis->GetMaximum();
  return hi > lo ? a + (value - lo) / (hi - lo) * (b - a) : a;
}

}  // namespace

Rgb chartSeriesColour(std::size_t index) {
  const auto& c = kOkabeIto[index % kOkabeIto.size()];
  return {c[0] / 255.0, c[1] / 255.0, c[2] / 255.0};
}

LineChartFigure writeLineChart(const LineChart& chart, const std::filesystem::path& png) {
  const double f = std::max(chart.width, 400) / 1200.0;
  auto xy = vtkSmartPointer<vtkChartXY>::New();
  xy->SetTitle(chart.title);
  useLabelFont(xy->GetTitleProperties(), true);
  xy->GetTitleProperties()->SetFontSize(static_cast<int>(24 * f + 0.5));
  styleAxis(xy->GetAxis(vtkAxis::BOTTOM), chart.xLabel, f);
  styleAxis(xy->GetAxis(vtkAxis::LEFT), chart.yLabel, f);
  xy->SetShowLegend(false);  // drawn beside the chart below: VTK's sits over the plot area

  const std::vector<SeriesLook> looks = seriesLooks(chart);
  for (std::size_t i = 0; i < chart.series.size(); ++i) {
    const ChartSeries& series = chart.series[i];
    vtkPlot* plot = xy->AddPlot(vtkChart::LINE);
    plot->SetInputData(seriesTable(series), 0, 1);
    plot->SetLabel(series.name);
    const Rgb& c = looks[i].colour;
    plot->SetColor(static_cast<unsigned char>(std::lround(255 * c[0])),
                   static_cast<unsigned char>(std::lround(255 * c[1])),
                   static_cast<unsigned char>(std::lround(255 * c[2])), 255);
    plot->SetWidth(static_cast<float>(looks[i].width * f));
    if (auto* line = vtkPlotLine::SafeDownCast(plot)) {
      line->SetMarkerStyle(looks[i].marker);
      line->SetMarkerSize(static_cast<float>(looks[i].markerSize * f));
    }
  }

  // A margin on every side: VTK lays the chart out to the window's edge, where the last tick
  // label and the outermost markers would be cut. The legend takes a column on the right, or a
  // band at the bottom when its names would leave the plot too narrow.
  LineChartFigure figure;
  const double margin = 24 * f, width = chart.width, height = chart.height;
  const LegendLayout legend = legendLayout(chart, f);
  figure.chart = {{margin, margin}, {width - margin, height - margin}};
  if (!chart.series.empty()) {
    if (legend.size.x() <= 0.4 * width) {
      figure.chart.hi.x() -= legend.size.x() + margin;
      const double top =
          height - margin - 60 * f;  // level with the plot area's top, under the title
      figure.legend = {{width - margin - legend.size.x(), top - legend.size.y()},
                       {width - margin, top}};
    } else {
      figure.chart.lo.y() += legend.size.y() + margin;
      figure.legend = {{margin + 60 * f, margin},
                       {margin + 60 * f + legend.size.x(), margin + legend.size.y()}};
    }
  }
  xy->SetAutoSize(false);
  const V2 size = figure.chart.hi - figure.chart.lo;
  xy->SetSize(vtkRectf(static_cast<float>(figure.chart.lo.x()),
                       static_cast<float>(figure.chart.lo.y()), static_cast<float>(size.x()),
                       static_cast<float>(size.y())));

  auto context = vtkSmartPointer<vtkContextActor>::New();
  context->GetScene()->AddItem(xy);
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor(context);
  if (!chart.series.empty()) addLegend(renderer, legend, looks, figure.legend, f);
  renderToPng(renderer, chart.width, chart.height, png);

  for (const ChartSeries& series : chart.series) {
    std::vector<V2>& points = figure.points.emplace_back();
    for (std::size_t k = 0; k < series.x.size(); ++k) {
      points.emplace_back(axisPixel(xy->GetAxis(vtkAxis::BOTTOM), series.x[k], false),
                          axisPixel(xy->GetAxis(vtkAxis::LEFT), series.y[k], true));
    }
  }
  return figure;
}

}  // namespace penumbra::viz
