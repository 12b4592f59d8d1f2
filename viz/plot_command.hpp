#pragma once
// `penumbra plot FOLDER` (and `penumbra grid ... --plot`): pictures and ParaView files of a
// finished grid run, written beside its results.
#include "viz/plot_options.hpp"

namespace penumbra::viz {

// Exit status: 0 done; 1 error (no display, results missing or malformed, device, options);
// 2 the scene is invalid. All files appear together, or none does. Messages go to stderr, the
// list of files to stdout.
int runPlotCommand(const PlotOptions& options);

}  // namespace penumbra::viz
