#include "viz/heat_map.hpp"

#include <fmt/format.h>
#include <vtkActor.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "viz/colour_legend.hpp"
#include "viz/false_colour.hpp"
#include "viz/field_surface.hpp"
#include "viz/isolux_labels.hpp"
#include "viz/isolux_lines.hpp"
#include "viz/nice_numbers.hpp"
#include "viz/overlay.hpp"
#include "viz/plan_symbols.hpp"
#include "viz/plane_sections.hpp"
#include "viz/plot_axes.hpp"
#include "viz/polygon2d.hpp"
#include "viz/render_png.hpp"

namespace penumbra::viz {

namespace {

using V2 = Eigen::Vector2d;

constexpr Rgb kWall{0.55, 0.55, 0.55};     // room slabs in section, as on an architect's plan
constexpr Rgb kOpening{0.78, 0.88, 0.97};  // glass blue
constexpr double kFootprintDash = 9.0;     // px at font scale 1
constexpr double kKeyLine = 24.0;          // px between the key's lines at font scale 1

// The grid points of the largest and smallest E among those not inside solids.
struct Extremes {
  int eMax = -1, eMin = -1;
};

Extremes findExtremes(const PlanarField& field) {
  Extremes x;
  for (int i = 0; i < static_cast<int>(field.illuminance.size()); ++i) {
    if (!field.valid[i]) continue;
    if (x.eMax < 0 || field.illuminance[i] > field.illuminance[x.eMax]) x.eMax = i;
    if (x.eMin < 0 || field.illuminance[i] < field.illuminance[x.eMin]) x.eMin = i;
  }
  return x;
}

V2 plotOf(const PlanarField& field, int index) {
  return field.plotAt(index % field.columns, index / field.columns);
}

std::vector<V2> project(const PlanarField& field, const std::vector<Vec3>& polygon) {
  std::vector<V2> points;
  for (const Vec3& p : polygon) points.push_back(field.plot.project(p));
  return points;
}

V2 boxArea(const V2& lo, const V2& hi) {
  return hi - lo;
}

// The plot area: the calculation area and what is around it (the room, the solids the plane
// cuts). A small grid in a large room (a desk top) is shown with a band of its surroundings
// rather than lost in the whole plan.
std::pair<V2, V2> plotBounds(vtkPolyData* surface, const std::vector<Polygon2>& shapes) {
  double b[6];
  surface->GetBounds(b);
  const V2 areaLo{b[0], b[2]}, areaHi{b[1], b[3]};
  V2 lo = areaLo, hi = areaHi;
  for (const Polygon2& shape : shapes) {
    for (const V2& p : shape) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  const V2 area = boxArea(areaLo, areaHi), all = boxArea(lo, hi);
  if (area.x() * area.y() < 0.2 * all.x() * all.y()) {
    const double band = std::max(0.5, 0.35 * area.maxCoeff());
    lo = lo.cwiseMax(areaLo - V2(band, band));
    hi = hi.cwiseMin(areaHi + V2(band, band));
  }
  const double pad = 0.03 * (hi - lo).maxCoeff();
  return {lo - V2(pad, pad), hi + V2(pad, pad)};
}

// A convex polygon in plot coordinates, cut to the plot area, in pixels; empty when outside.
std::vector<V2> toPixels(const PlotLayout& layout, const Polygon2& polygon) {
  std::vector<V2> pixels;
  for (const V2& p : clipToBox(polygon, {layout.s0, layout.t0}, {layout.s1, layout.t1})) {
    pixels.push_back(layout.pixel(p));
  }
  return pixels;
}

// A solid's name in the middle of its outline (`pixels`).
void addSolidName(vtkRenderer* renderer, const PlotLayout& layout, const std::string& text,
                  const std::vector<V2>& pixels) {
  TextStyle name;
  name.size = layout.scaled(14);
  name.horizontal = Align::Centre;
  name.vertical = Align::Centre;
  name.colour = kSubtle;
  name.box = true;
  V2 centre = V2::Zero();
  for (const V2& p : pixels) centre += p;
  renderer->AddActor2D(textAt(text, centre / static_cast<double>(pixels.size()), name));
}

void addSections(vtkRenderer* renderer, const PlotLayout& layout, const PlanarField& field,
                 const std::vector<SolidSection>& sections, HeatMapFigure& figure) {
  for (const SolidSection& section : sections) {
    const std::vector<V2> pixels = toPixels(layout, project(field, section.polygon));
    if (pixels.empty()) continue;
    if (section.roomSlab) {
      renderer->AddActor2D(fillAt(pixels, kWall));
      continue;
    }
    // Furniture through the plane: hatched grey over the colours, outlined, named.
    figure.sections.emplace_back(section.name, project(field, section.polygon));
    renderer->AddActor2D(fillAt(pixels, kWhite, 0.55));
    renderer->AddActor2D(lineAt(pixels, true, kInk, 1.5 * layout.fontScale));
    addSolidName(renderer, layout, section.name, pixels);
  }
}

// Footprints of furniture wholly above the plane that overlap the calculation area [lo, hi]:
// dashed outlines, so that the colours under them stay readable, named like the sections.
void addFootprints(vtkRenderer* renderer, const PlotLayout& layout, const PlanarField& field,
                   const std::vector<SolidSection>& footprints, const V2& lo, const V2& hi,
                   HeatMapFigure& figure) {
  for (const SolidSection& footprint : footprints) {
    const Polygon2 plotted = project(field, footprint.polygon);
    // Over the calculation area: sharing more than an edge with it.
    if (std::abs(signedArea(clipToBox(plotted, lo, hi))) <= 1e-9 * (hi - lo).prod()) continue;
    const std::vector<V2> pixels = toPixels(layout, plotted);
    if (pixels.empty()) continue;
    figure.footprints.emplace_back(footprint.name, plotted);
    renderer->AddActor2D(dashedLineAt(pixels, true, kWhite, 4.5 * layout.fontScale,
                                      kFootprintDash * layout.fontScale));
    renderer->AddActor2D(
        dashedLineAt(pixels, true, kInk, 2 * layout.fontScale, kFootprintDash * layout.fontScale));
    addSolidName(renderer, layout, footprint.name, pixels);
  }
}

// A line of the key under the legend: a square drawn as the thing it names.
struct KeyEntry {
  std::string text;
  Rgb fill, edge;
  bool filled = true, dashed = false;
};

// Openings in their walls and luminaires as they project onto the picture. Returns the key's
// entries for them and for the furniture drawn (figure.sections, figure.footprints).
std::vector<KeyEntry> addPlanSymbols(vtkRenderer* renderer, const PlotLayout& layout,
                                     const PlotPlane& plot, const Scene& scene,
                                     const HeatMapFigure& figure) {
  const double f = layout.fontScale;
  bool anyOpening = false, anyLuminaire = false;
  for (const PlotPolygon& opening : projectedOpenings(scene, plot)) {
    const std::vector<V2> pixels = toPixels(layout, opening);
    if (pixels.empty()) continue;
    renderer->AddActor2D(fillAt(pixels, kOpening));
    renderer->AddActor2D(lineAt(pixels, true, kInk, f));
    anyOpening = true;
  }
  for (const PlotPolygon& luminaire : projectedLuminaires(scene, plot)) {
    const std::vector<V2> pixels = toPixels(layout, luminaire);
    if (pixels.empty()) continue;
    renderer->AddActor2D(lineAt(pixels, true, kSourceEdge, 2 * f));
    anyLuminaire = true;
  }
  std::vector<KeyEntry> entries;
  if (anyLuminaire) entries.push_back({"luminaire (projected)", kWhite, kSourceEdge});
  if (anyOpening) entries.push_back({"opening", kOpening, kInk});
  if (!figure.sections.empty()) {
    entries.push_back({"cut by the plane", {0.8, 0.8, 0.8}, kInk});
  }
  if (!figure.footprints.empty()) {
    entries.push_back({"above the plane", kWhite, kInk, false, true});
  }
  return entries;
}

// The key, its first line's square at `at` (lower-left corner, px), each next line 24 px lower.
void addKey(vtkRenderer* renderer, const PlotLayout& layout, const std::vector<KeyEntry>& entries,
            V2 at) {
  const double f = layout.fontScale;
  TextStyle key;
  key.size = layout.scaled(15);
  key.vertical = Align::Centre;
  const double box = 14 * f;
  for (const KeyEntry& e : entries) {
    const std::vector<V2> square{
        at, {at.x() + box, at.y()}, {at.x() + box, at.y() + box}, {at.x(), at.y() + box}};
    if (e.filled) renderer->AddActor2D(fillAt(square, e.fill));
    renderer->AddActor2D(e.dashed ? dashedLineAt(square, true, e.edge, 2 * f, 0.3 * box)
                                  : lineAt(square, true, e.edge, 2 * f));
    renderer->AddActor2D(textAt(e.text, {at.x() + box + 8 * f, at.y() + box / 2}, key));
    at.y() -= kKeyLine * f;
  }
}

void addMarker(vtkRenderer* renderer, const PlotLayout& layout, const V2& at, bool isMax,
               const std::string& text) {
  const double f = layout.fontScale;
  const double r = 12 * f;
  // A ring (Emax) or a square (Emin), black under white so that it shows on any colour; hollow,
  // so that the colour at the point itself stays visible.
  const std::vector<V2> shape = isMax ? circle(at, r)
                                      : std::vector<V2>{{at.x() - r, at.y() - r},
                                                        {at.x() + r, at.y() - r},
                                                        {at.x() + r, at.y() + r},
                                                        {at.x() - r, at.y() + r}};
  renderer->AddActor2D(lineAt(shape, true, kInk, 5 * f));
  renderer->AddActor2D(lineAt(shape, true, kWhite, 2 * f));
  TextStyle label;
  label.size = layout.scaled(17);
  label.bold = true;
  label.box = true;
  label.vertical = Align::Centre;
  // Right of the marker, or left of it near the plot's right edge.
  const bool leftSide = at.x() > layout.pixel({layout.s1, layout.t1}).x() - 200 * f;
  label.horizontal = leftSide ? Align::End : Align::Start;
  const double dx = (r + 8 * f) * (leftSide ? -1 : 1);
  renderer->AddActor2D(textAt(text, {at.x() + dx, at.y()}, label));
}

// " lx" after a reading, nothing for a quantity without a unit.
std::string unitSuffix(const FieldQuantity& q) {
  return q.unit.empty() ? "" : " " + q.unit;
}

void addTitle(vtkRenderer* renderer, const PlotLayout& layout, const PlanarField& field,
              const GridMetrics& m, const HeatMapStyle& style) {
  const double x = layout.left;
  double y = layout.height - layout.scaled(20);
  TextStyle title;
  title.size = layout.scaled(26);
  title.bold = true;
  title.vertical = Align::End;
  renderer->AddActor2D(
      textAt(fmt::format("{}: {}", field.name, style.quantity.title), {x, y}, title));
  y -= layout.scaled(38);
  TextStyle metrics = title;
  metrics.size = layout.scaled(21);
  metrics.bold = false;
  const std::string line =
      !style.quantity.metricsLine.empty()
          ? style.quantity.metricsLine
          : fmt::format(
                "Eavg {} lx    Emin {} lx    Emax {} lx    U0 = Emin/Eavg {:.3f}    "
                "Ud = Emin/Emax {:.3f}",
                formatReading(m.eAvg), formatReading(m.eMin), formatReading(m.eMax), m.u0, m.ud);
  renderer->AddActor2D(textAt(line, {x, y}, metrics));
  y -= layout.scaled(32);
  TextStyle note = metrics;
  note.size = layout.scaled(16);
  note.colour = kSubtle;
  renderer->AddActor2D(textAt(style.subtitle, {x, y}, note));
}

}  // namespace

HeatMapFigure drawHeatMap(const PlanarField& field, const GridMetrics& metrics, const Scene& scene,
                          const HeatMapStyle& style, const std::filesystem::path& png) {
  HeatMapFigure figure;
  vtkSmartPointer<vtkPolyData> surface = fieldSurface(field, fieldSubdivisions(field));
  figure.isolux = isoluxLines(surface, style.isolux);

  const Plane plane = Plane::through(field.first, field.normal);
  const std::vector<SolidSection> sections = solidSections(scene, plane);
  const std::vector<SolidSection> footprints = solidFootprints(scene, plane);
  const std::vector<V2> outline = project(field, roomOutline(scene, plane));
  std::vector<Polygon2> shapes{outline};
  for (const SolidSection& s : sections) shapes.push_back(project(field, s.polygon));
  const auto [lo, hi] = plotBounds(surface, shapes);
  figure.layout = plotLayout(lo, hi, style.width);
  const PlotLayout& layout = figure.layout;
  const double f = layout.fontScale;

  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->AddActor(falseColourActor(surface, style.scale));
  vtkSmartPointer<vtkActor> lines = plainActor(figure.isolux, kInk, 1.6 * f);
  lines->SetPosition(0.0, 0.0, 0.01);  // towards the camera: over the colours
  renderer->AddActor(lines);

  addSections(renderer, layout, field, sections, figure);
  double area[6];
  surface->GetBounds(area);
  addFootprints(renderer, layout, field, footprints, {area[0], area[2]}, {area[1], area[3]},
                figure);
  const std::vector<KeyEntry> key = addPlanSymbols(renderer, layout, field.plot, scene, figure);
  // Under the colour bar; a long key lifts the bar rather than leave the image at its bottom.
  const double keyTop = std::max(layout.bottom - 36 * f,
                                 14 * f + kKeyLine * f * (static_cast<double>(key.size()) - 1.0));
  addKey(renderer, layout, key, {layout.width - 230 * f, keyTop});
  if (const std::vector<V2> pixels = toPixels(layout, outline); !pixels.empty()) {
    renderer->AddActor2D(lineAt(pixels, true, kInk, 2.5 * f));
  }

  const Extremes extremes = findExtremes(field);
  std::vector<V2> markers;
  if (extremes.eMax >= 0) {
    figure.eMaxAt = plotOf(field, extremes.eMax);
    figure.eMinAt = plotOf(field, extremes.eMin);
    markers = {layout.pixel(figure.eMaxAt), layout.pixel(figure.eMinAt)};
  }
  TextStyle levelStyle;
  levelStyle.size = layout.scaled(15);
  levelStyle.horizontal = Align::Centre;
  levelStyle.vertical = Align::Centre;
  levelStyle.box = true;
  for (const IsoluxLabel& label : placeIsoluxLabels(figure.isolux, layout, markers)) {
    const FieldQuantity& q = style.quantity;
    const std::string level = q.levelDigits > 0 ? fmt::format("{:.{}g}", label.level, q.levelDigits)
                                                : formatTick(label.level, label.level);
    renderer->AddActor2D(textAt(q.levelPrefix + level + unitSuffix(q), label.pixel, levelStyle));
  }
  if (extremes.eMax >= 0) {
    const FieldQuantity& q = style.quantity;
    addMarker(
        renderer, layout, markers[1], false,
        q.extremeLabel + "min " + formatReading(field.illuminance[extremes.eMin]) + unitSuffix(q));
    addMarker(
        renderer, layout, markers[0], true,
        q.extremeLabel + "max " + formatReading(field.illuminance[extremes.eMax]) + unitSuffix(q));
  }

  addPlotAxes(renderer, layout, field.plot.sLabel, field.plot.tLabel);
  addTitle(renderer, layout, field, metrics, style);
  LegendPlacement& legend = figure.legend;
  legend.fontScale = f;
  legend.x = layout.width - 230 * f;
  legend.y = std::max(layout.bottom, keyTop + 36 * f);
  legend.width = 30 * f;
  legend.height = std::max(layout.plotHeight() - 80 * f - (legend.y - layout.bottom), 200 * f);
  addColourLegend(renderer, style.scale, legend, style.quantity.legendTitle, style.isolux);

  placeCamera(renderer, layout);
  renderToPng(renderer, layout.width, layout.height, png);
  return figure;
}

}  // namespace penumbra::viz
