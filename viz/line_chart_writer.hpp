#pragma once
// Sweep charts: a metric against a parameter, one line per series (VTK Charts), to PNG.
#include <cstddef>
#include <filesystem>

#include "output/line_chart.hpp"
#include "viz/rgb.hpp"

namespace penumbra::viz {

// Draws `chart` at chart.width × chart.height px: one line with markers per series, in a
// colour-blind-safe palette, a legend with the series' names, the axis titles as given (with
// their units) and the title. Needs a display (render_png.hpp). Throws std::invalid_argument
// for a series whose x and y differ in length, std::runtime_error when the file cannot be written.
void writeLineChart(const LineChart& chart, const std::filesystem::path& png);

// The colour of series `index` (Okabe and Ito's palette, repeating after eight).
Rgb chartSeriesColour(std::size_t index);

}  // namespace penumbra::viz
