#pragma once
// From illuminance to colour: the range of the legend, linear or logarithmic, and the palette.
// Every picture of a run uses one ColourScale per quantity, built here.
#include <array>
#include <string>
#include <vector>

#include <vtkLookupTable.h>
#include <vtkSmartPointer.h>

#include "viz/plot_options.hpp"
#include "viz/rgb.hpp"

namespace penumbra::viz {

struct ColourScale {
  double min = 0.0;  // lx: values at or below get the first colour
  double max = 1.0;  // lx: values at or above get the last colour
  bool log = false;
  Palette palette = Palette::Viridis;

  // Where `value` sits on the legend: 0 at min, 1 at max (clamped), linear or in log10.
  double fraction(double value) const;
  // The inverse of fraction().
  double valueAt(double fraction) const;
};

// The scale for data spanning [dataMin, dataMax] lx. --range when given; otherwise linear from 0
// to a round value at or above dataMax, or logarithmic between the 1-2-5 values around the data.
// Throws std::invalid_argument for a range with max <= min, or min <= 0 on a log scale.
ColourScale colourScale(const LegendOptions& options, double dataMin, double dataMax);

// The palette at t in [0, 1], RGB in [0, 1].
Rgb paletteColour(Palette palette, double t);

// 256 colours over [min, max]; out-of-range values clamp to the end colours.
vtkSmartPointer<vtkLookupTable> lookupTable(const ColourScale& scale);

// Round values to label the legend with (linear: multiples of a 1-2-5 step; log: 1-2-5 values).
std::vector<double> legendTicks(const ColourScale& scale);

// A tick as the legend writes it: just the digits the tick step needs ("0.5", "200").
std::string tickLabel(const ColourScale& scale, double tick);

}  // namespace penumbra::viz
