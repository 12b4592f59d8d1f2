#include "viz/colour_scale.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <stdexcept>

#include "viz/nice_numbers.hpp"

namespace penumbra::viz {

namespace {

// Viridis (van der Walt and Smith, matplotlib's default) at t = 0, 0.1, …, 1; linear
// interpolation between these is within a few units of 255 of the full 256-colour table.
constexpr std::array<Rgb, 11> kViridis{{
    {0x44 / 255.0, 0x01 / 255.0, 0x54 / 255.0},
    {0x48 / 255.0, 0x25 / 255.0, 0x76 / 255.0},
    {0x41 / 255.0, 0x44 / 255.0, 0x87 / 255.0},
    {0x35 / 255.0, 0x5f / 255.0, 0x8d / 255.0},
    {0x2a / 255.0, 0x78 / 255.0, 0x8e / 255.0},
    {0x21 / 255.0, 0x91 / 255.0, 0x8c / 255.0},
    {0x22 / 255.0, 0xa8 / 255.0, 0x84 / 255.0},
    {0x42 / 255.0, 0xbe / 255.0, 0x71 / 255.0},
    {0x7a / 255.0, 0xd1 / 255.0, 0x51 / 255.0},
    {0xbd / 255.0, 0xdf / 255.0, 0x26 / 255.0},
    {0xfd / 255.0, 0xe7 / 255.0, 0x25 / 255.0},
}};

// The look of Radiance's falsecolor scale, sampled at t = 0, 1/8, …, 1: what Radiance users
// are used to reading. Not perceptually uniform (the brown middle is darker than its ends).
constexpr std::array<Rgb, 9> kFalseColor{{
    {0.43, 0.03, 0.52},
    {0.00, 0.12, 0.71},
    {0.02, 0.58, 0.70},
    {0.12, 0.66, 0.23},
    {0.53, 0.42, 0.31},
    {0.60, 0.25, 0.24},
    {0.66, 0.07, 0.11},
    {0.99, 0.48, 0.00},
    {0.99, 0.98, 0.16},
}};

Rgb interpolate(std::span<const Rgb> stops, double t) {
  t = std::clamp(t, 0.0, 1.0) * static_cast<double>(stops.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(t), stops.size() - 2);
  const double f = t - static_cast<double>(i);
  Rgb c{};
  for (int k = 0; k < 3; ++k) c[k] = (1.0 - f) * stops[i][k] + f * stops[i + 1][k];
  return c;
}

// Linear tick step: a 1-2-5 value giving at most about eight intervals.
double linearStep(const ColourScale& scale) {
  return oneTwoFiveAtLeast((scale.max - scale.min) / 8);
}

}  // namespace

double ColourScale::fraction(double value) const {
  double f = 0.0;
  if (log) {
    if (!(value > 0.0)) return 0.0;
    f = (std::log10(value) - std::log10(min)) / (std::log10(max) - std::log10(min));
  } else {
    f = (value - min) / (max - min);
  }
  return std::clamp(f, 0.0, 1.0);
}

double ColourScale::valueAt(double f) const {
  if (log) return std::pow(10.0, std::log10(min) + f * (std::log10(max) - std::log10(min)));
  return min + f * (max - min);
}

ColourScale colourScale(const LegendOptions& options, double dataMin, double dataMax) {
  ColourScale scale;
  scale.log = options.log;
  scale.palette = options.palette;
  if (options.range) {
    scale.min = options.range->first;
    scale.max = options.range->second;
    if (!(scale.max > scale.min)) {
      throw std::invalid_argument(fmt::format(
          "--range {}:{}: the maximum must be above the minimum", scale.min, scale.max));
    }
    if (scale.log && !(scale.min > 0.0)) {
      throw std::invalid_argument(
          fmt::format("--range {}:{} with --log: a logarithmic legend needs a minimum above 0 lx",
                      scale.min, scale.max));
    }
    return scale;
  }
  // Data that is all dark (or undefined) still gets a legend one can read.
  const double top = std::isfinite(dataMax) && dataMax > 0.0 ? dataMax : 1.0;
  if (scale.log) {
    scale.max = oneTwoFiveAtLeast(top);
    // Shadows at 0 lx would send a log scale to -infinity: start three decades below the top.
    const double bottom = std::isfinite(dataMin) && dataMin > 0.0 ? dataMin : 0.0;
    scale.min = oneTwoFiveAtMost(std::max(bottom, scale.max * 1e-3));
    if (!(scale.max > scale.min)) scale.min = oneTwoFiveAtMost(scale.max * 0.99);
  } else {
    scale.min = 0.0;
    const double step = oneTwoFiveAtLeast(top / 8);
    scale.max = std::ceil(top / step * (1.0 - 1e-12)) * step;
  }
  return scale;
}

Rgb paletteColour(Palette palette, double t) {
  return palette == Palette::Viridis ? interpolate(kViridis, t) : interpolate(kFalseColor, t);
}

vtkSmartPointer<vtkLookupTable> lookupTable(const ColourScale& scale) {
  constexpr int kColours = 256;
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(kColours);
  for (int i = 0; i < kColours; ++i) {
    const Rgb c = paletteColour(scale.palette, i / double(kColours - 1));
    table->SetTableValue(i, c[0], c[1], c[2], 1.0);
  }
  table->SetTableRange(scale.min, scale.max);
  if (scale.log) table->SetScaleToLog10();
  table->SetNanColor(0.75, 0.75, 0.75, 1.0);
  return table;
}

std::string tickLabel(const ColourScale& scale, double tick) {
  return formatTick(tick, scale.log ? tick : linearStep(scale));
}

std::vector<double> legendTicks(const ColourScale& scale) {
  if (!scale.log) return multiplesOf(linearStep(scale), scale.min, scale.max);
  std::vector<double> ticks;
  const double decades = std::log10(scale.max / scale.min);
  for (double v : oneTwoFiveBetween(scale.min * 0.999, scale.max * 1.001)) {
    // Beyond three decades 2 and 5 crowd the legend: powers of ten only.
    const double mantissa = v / std::pow(10.0, std::floor(std::log10(v) + 1e-9));
    if (decades <= 3.0 || std::abs(mantissa - 1.0) < 1e-6) ticks.push_back(v);
  }
  return ticks;
}

}  // namespace penumbra::viz
