#include "viz/plot_axes.hpp"

#include <algorithm>

#include "viz/nice_numbers.hpp"
#include "viz/overlay.hpp"

namespace penumbra::viz {

void addPlotAxes(vtkRenderer* renderer, const PlotLayout& layout, const std::string& sTitle,
                 const std::string& tTitle) {
  using V = Eigen::Vector2d;
  const V lowerLeft = layout.pixel({layout.s0, layout.t0});
  const V upperRight = layout.pixel({layout.s1, layout.t1});
  renderer->AddActor2D(lineAt(
      {lowerLeft, {upperRight.x(), lowerLeft.y()}, upperRight, {lowerLeft.x(), upperRight.y()}},
      true, kInk, 1.5 * layout.fontScale));

  // One step for both axes (about ten ticks along the longer one): a metre is as long across
  // as up, and the labels say so.
  const double step =
      oneTwoFiveAtLeast(std::max(layout.s1 - layout.s0, layout.t1 - layout.t0) / 10.0);
  const double tick = layout.scaled(8);
  TextStyle label;
  label.size = layout.scaled(18);

  label.horizontal = Align::Centre;
  label.vertical = Align::End;
  for (double s : multiplesOf(step, layout.s0, layout.s1)) {
    const V p = layout.pixel({s, layout.t0});
    renderer->AddActor2D(lineAt({p, {p.x(), p.y() - tick}}, false, kInk, layout.fontScale));
    renderer->AddActor2D(textAt(formatTick(s, step), {p.x(), p.y() - tick - 4}, label));
  }
  label.horizontal = Align::End;
  label.vertical = Align::Centre;
  for (double t : multiplesOf(step, layout.t0, layout.t1)) {
    const V p = layout.pixel({layout.s0, t});
    renderer->AddActor2D(lineAt({p, {p.x() - tick, p.y()}}, false, kInk, layout.fontScale));
    renderer->AddActor2D(textAt(formatTick(t, step), {p.x() - tick - 6, p.y()}, label));
  }

  TextStyle title;
  title.size = layout.scaled(20);
  title.horizontal = Align::Centre;
  title.vertical = Align::End;
  renderer->AddActor2D(textAt(
      sTitle, {(lowerLeft.x() + upperRight.x()) / 2, lowerLeft.y() - tick - layout.scaled(36)},
      title));
  title.angle = 90.0;
  title.vertical = Align::Start;
  renderer->AddActor2D(textAt(
      tTitle, {lowerLeft.x() - tick - layout.scaled(62), (lowerLeft.y() + upperRight.y()) / 2},
      title));
}

}  // namespace penumbra::viz
