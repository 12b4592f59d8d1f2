#pragma once
// The charts of a sweep: each metric against each varied parameter, as data (drawing is viz/'s
// job; the sweep hands these to a chart writer hook).
#include <string>
#include <vector>

#include "output/sweep_files.hpp"
#include "study/study_layout.hpp"

namespace penumbra {

// For every grid, metric and parameter that takes more than one value: one chart. With the
// `grid` combination each combination of the other varied parameters is a series of its own
// ("panel_flux_lm = 3000"); with `zip` the parameters move together, so there is one series.
// Points are sorted by x; undefined metrics (NaN) are left out, and a chart with no point left
// (a point list's U0, undefined in every case) is not drawn. File names are
// "<metric column>-vs-<parameter>.png".
std::vector<ChartFile> studyCharts(const StudyLayout& layout,
                                   const std::vector<CaseRecord>& records);

}  // namespace penumbra
