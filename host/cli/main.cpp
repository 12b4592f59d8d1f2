// penumbra's command line: parses with CLI11 and hands over to one function per subcommand.
#include <CLI/CLI.hpp>

#include "cli/devices_command.hpp"
#include "cli/glare_options.hpp"
#include "cli/grid_command.hpp"
#include "cli/help_text.hpp"
#include "cli/luminaire_options.hpp"
#include "cli/option_checks.hpp"
#include "cli/render_command.hpp"
#include "cli/render_options.hpp"
#include "cli/sweep_options.hpp"
#include "cli/tonemap_options.hpp"
#include "cli/version.hpp"
#include "cluster/child_process.hpp"
#include "memory/heap_settings.hpp"
#include "output/interrupt_cleanup.hpp"
#include "viz/case_plots.hpp"
#include "viz/isoband_svg.hpp"
#include "viz/line_chart_writer.hpp"
#include "viz/plot_cli.hpp"
#include "viz/plot_command.hpp"
#include "viz/render_png.hpp"

int main(int argc, char** argv) {
  penumbra::keepFreedBlocksInTheHeap();
  // Before any thread starts: Ctrl-C or SIGTERM then leaves no staging directory behind.
  penumbra::removeStagingOnInterrupt();
  CLI::App app{penumbra::help::kProgram, "penumbra"};
  app.footer(penumbra::help::kProgramFooter);
  app.set_version_flag("--version", std::string("penumbra ") + penumbra::kVersion);
  app.require_subcommand(1);

  penumbra::GridOptions grid;
  CLI::App* gridCommand = app.add_subcommand("grid", penumbra::help::kGrid);
  gridCommand->footer(penumbra::help::kGridFooter);
  gridCommand->add_option("scene", grid.scene, "Scene file (YAML, scene format v1)")->required();
  gridCommand->add_option("-o,--output", grid.output, "Output directory (created if missing)")
      ->required();
  penumbra::cli::addEstimatorOptions(*gridCommand, grid.estimator);
  // One name per --grid, so that `--grid a scene.yaml` does not swallow the scene.
  gridCommand
      ->add_option("--grid", grid.grids,
                   "Compute only this grid (repeat for several; default: all)")
      ->allow_extra_args(false);
  gridCommand->add_flag("-q,--quiet", grid.quiet, "No progress and no table; errors only");
  bool gridNoCulling = false;
  gridCommand->add_flag("--no-culling", gridNoCulling,
                        "Test every occluder at every point (no shadow volumes): slower, the same "
                        "numbers; for comparison");
  std::vector<std::string> gridSettings;
  gridCommand
      ->add_option("--set", gridSettings,
                   "Give a scene parameter a value other than its default: NAME=VALUE (repeat "
                   "for several)")
      ->allow_extra_args(false)
      ->check(penumbra::cli::kParameterAssignment);
  bool plotAfterGrid = false;
  penumbra::viz::PlotOptions gridPlot;
  penumbra::viz::addPlotFlag(*gridCommand, plotAfterGrid, gridPlot);

  penumbra::RenderCommandOptions render;
  std::vector<std::string> renderSettings;
  bool renderNoCulling = false;
  CLI::App* renderCommand =
      penumbra::cli::addRenderCommand(app, render, renderSettings, renderNoCulling);
  // The vector drawings come from viz/ (host/ never includes it).
  render.vectorDrawing = [](const penumbra::Scene& scene, const penumbra::RenderedView& rendered,
                            penumbra::compute::Device& device, int bands,
                            const std::filesystem::path& folder) {
    penumbra::IlluminanceEngine engine(device, scene);
    penumbra::viz::writeViewIsobandFiles(scene, rendered, penumbra::viz::directLight(engine), bands,
                                         folder);
  };

  penumbra::SweepOptions sweep;
  CLI::App* sweepCommand = penumbra::cli::addSweepCommand(app, sweep);
  penumbra::MergeOptions merge;
  CLI::App* mergeCommand = penumbra::cli::addMergeCommand(app, merge);
  // Sweep charts are drawn by viz/ (host/ never includes it). VTK aborts the process when its X
  // display is missing or goes away: without a display the sweep says how to get charts, and
  // with one the charts are drawn in a child process, so that an abort there costs the charts
  // not yet drawn, never the results.
  const penumbra::ChartDrawing drawCharts = [](const std::vector<penumbra::ChartFile>& charts,
                                               const std::filesystem::path& directory) {
    penumbra::runInChildProcess([&] {
      for (const penumbra::ChartFile& c : charts) {
        penumbra::viz::writeLineChart(c.chart, directory / c.fileName);
      }
    });
  };
  sweep.charts = merge.charts = {drawCharts, penumbra::viz::displayUnavailable()};

  penumbra::ToneMapCommandOptions toneMap;
  CLI::App* toneMapCommand = penumbra::cli::addToneMapCommand(app, toneMap);

  CLI::App* devicesCommand = app.add_subcommand("devices", penumbra::help::kDevices);

  penumbra::GlareOptions glare;
  std::vector<std::string> glareSettings;
  CLI::App* glareCommand = penumbra::cli::addGlareCommand(app, glare, glareSettings);

  penumbra::LuminaireOptions luminaire;
  CLI::App* luminaireCommand = penumbra::cli::addLuminaireCommand(app, luminaire);

  penumbra::viz::PlotOptions plot;
  CLI::App* plotCommand = penumbra::viz::addPlotCommand(app, plot);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with status 0; every real usage error is status 1 (2 is
    // reserved for an invalid scene).
    const int status = app.exit(e);
    return status == 0 ? 0 : 1;
  }
  if (*gridCommand) {
    grid.estimator.culling = !gridNoCulling;
    grid.parameters = penumbra::cli::parameterAssignments(gridSettings);
    const int status = penumbra::runGridCommand(grid);
    if (status != 0 || !plotAfterGrid) return status;
    gridPlot.folder = grid.output;
    gridPlot.device = grid.estimator.device;
    gridPlot.quiet = grid.quiet;
    return penumbra::viz::runPlotCommand(gridPlot);
  }
  if (*renderCommand) {
    render.estimator.culling = !renderNoCulling;
    render.parameters = penumbra::cli::parameterAssignments(renderSettings);
    return penumbra::runRenderCommand(render);
  }
  if (*plotCommand) return penumbra::viz::runPlotCommand(plot);
  if (*sweepCommand) {
    // Per-case plots (`plots: true`) with the sweep's device and the plot defaults.
    penumbra::viz::PlotOptions casePlots;
    casePlots.device = sweep.estimator.device;
    sweep.caseOutputs = {std::make_shared<penumbra::viz::CasePlots>(casePlots)};
    return penumbra::runSweepCommand(sweep);
  }
  if (*mergeCommand) return penumbra::runMergeCommand(merge);
  if (*toneMapCommand) return penumbra::runToneMapCommand(toneMap);
  if (*devicesCommand) return penumbra::runDevicesCommand();
  if (*glareCommand) {
    glare.parameters = penumbra::cli::parameterAssignments(glareSettings);
    return penumbra::runGlareCommand(glare);
  }
  if (*luminaireCommand) return penumbra::runLuminaireCommand(luminaire);
  return 1;
}
