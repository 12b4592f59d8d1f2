#pragma once
// Where things go on a 2-D figure (heat map): a plot area drawn to scale (1 m across = 1 m up),
// with margins for the title above, the axes left and below, and the legend on the right.
#include <vtkRenderer.h>
#include <Eigen/Core>

namespace penumbra::viz {

struct PlotLayout {
  int width = 0, height = 0;              // the image, px
  double s0 = 0, s1 = 1, t0 = 0, t1 = 1;  // the plot area in plot coordinates, m
  double left = 0, bottom = 0;  // px from the image's lower-left corner to the plot area's
  double pxPerMetre = 1.0;
  double fontScale = 1.0;  // fonts and line widths grow with the width (1 at 1600 px)

  double plotWidth() const { return (s1 - s0) * pxPerMetre; }
  double plotHeight() const { return (t1 - t0) * pxPerMetre; }
  // Plot coordinates (m) to pixels from the image's lower-left corner (VTK's display
  // coordinates; a PNG stores rows from the top: row = height - 1 - y).
  Eigen::Vector2d pixel(const Eigen::Vector2d& st) const {
    return {left + (st.x() - s0) * pxPerMetre, bottom + (st.y() - t0) * pxPerMetre};
  }
  int scaled(double px) const { return static_cast<int>(px * fontScale + 0.5); }
};

// The layout for a plot area of `min`..`max` (m) in an image `width` px wide; the height
// follows from the plot's aspect ratio.
PlotLayout plotLayout(const Eigen::Vector2d& min, const Eigen::Vector2d& max, int width);

// A parallel camera looking down on z = 0 so that plot point (s, t, 0) lands on pixel(s, t).
void placeCamera(vtkRenderer* renderer, const PlotLayout& layout);

}  // namespace penumbra::viz
