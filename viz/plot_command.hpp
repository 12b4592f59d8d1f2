#pragma once
// `penumbra plot FOLDER` (and `penumbra grid ... --plot`): pictures and ParaView files of a
// finished grid run, written beside its results.
#include <string>
#include <vector>

#include "output/run_report.hpp"
#include "viz/plot_options.hpp"

namespace penumbra::viz {

// The files a plot of `run` writes: per planar grid <stem>.png and <stem>.vti, per point list
// <stem>.vtp, and surfaces.vtp + surfaces.png when the scene has solids. Throws
// std::runtime_error when two would share a name (a grid called "surfaces").
std::vector<std::string> plotFileNames(const RunReport& run, bool withSurfaces);

// Exit status: 0 done; 1 error (no display, results missing or malformed, device, options);
// 2 the scene is invalid. All files appear together, or none does. Messages go to stderr, the
// list of files to stdout.
int runPlotCommand(const PlotOptions& options);

}  // namespace penumbra::viz
