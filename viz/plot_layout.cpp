#include "viz/plot_layout.hpp"

#include <vtkCamera.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace penumbra::viz {

namespace {

// Margins at 1600 px, scaled with the width: room for two title lines, tick labels and axis
// titles, and the legend with its labels.
constexpr double kReferenceWidth = 1600.0;
constexpr double kLeft = 120.0, kRight = 270.0, kTop = 120.0, kBottom = 100.0;
constexpr double kMinPlotHeight = 420.0;  // the legend needs this much
constexpr double kMaxAspect = 1.5;        // height of the image at most 1.5 × its width

}  // namespace

PlotLayout plotLayout(const Eigen::Vector2d& min, const Eigen::Vector2d& max, int width) {
  if (!(max.x() > min.x()) || !(max.y() > min.y())) {
    throw std::invalid_argument("plotLayout: empty plot area");
  }
  PlotLayout layout;
  layout.width = width;
  layout.fontScale = width / kReferenceWidth;
  layout.s0 = min.x();
  layout.s1 = max.x();
  layout.t0 = min.y();
  layout.t1 = max.y();
  const double f = layout.fontScale;
  const double availableWidth = width - (kLeft + kRight) * f;
  const double maxPlotHeight = kMaxAspect * width - (kTop + kBottom) * f;
  layout.pxPerMetre =
      std::min(availableWidth / (max.x() - min.x()), maxPlotHeight / (max.y() - min.y()));
  const double plotHeight = layout.plotHeight();
  const double areaHeight = std::max(plotHeight, kMinPlotHeight * f);
  layout.height = static_cast<int>(std::ceil((kTop + kBottom) * f + areaHeight));
  layout.left = kLeft * f + (availableWidth - layout.plotWidth()) / 2.0;
  layout.bottom = kBottom * f + (areaHeight - plotHeight) / 2.0;
  return layout;
}

void placeCamera(vtkRenderer* renderer, const PlotLayout& layout) {
  // The world point under the image's centre.
  const double s = layout.s0 + (layout.width / 2.0 - layout.left) / layout.pxPerMetre;
  const double t = layout.t0 + (layout.height / 2.0 - layout.bottom) / layout.pxPerMetre;
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(s, t, 0.0);
  camera->SetPosition(s, t, 10.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(layout.height / 2.0 / layout.pxPerMetre);
  renderer->ResetCameraClippingRange(s - 1e3, s + 1e3, t - 1e3, t + 1e3, -1.0, 1.0);
}

}  // namespace penumbra::viz
