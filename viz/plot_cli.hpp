#pragma once
// The command line of the plots, for main.cpp: the `plot` subcommand, and the `--plot` flag with
// the same options on `grid`. Parsing only; the work is runPlotCommand (plot_command.hpp).
#include <CLI/CLI.hpp>

#include "viz/plot_options.hpp"

namespace penumbra::viz {

// Adds `penumbra plot FOLDER [options]` to `app`, filling `options`.
CLI::App* addPlotCommand(CLI::App& app, PlotOptions& options);

// Adds `--plot` and the plot options to `gridCommand` (the options need --plot). The folder,
// device and quietness are the grid run's: main.cpp copies them over.
CLI::Option* addPlotFlag(CLI::App& gridCommand, bool& plot, PlotOptions& options);

}  // namespace penumbra::viz
