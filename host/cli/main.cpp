// penumbra's command line: parses with CLI11 and hands over to one function per subcommand.
#include <CLI/CLI.hpp>

#include "cli/devices_command.hpp"
#include "cli/grid_command.hpp"
#include "cli/help_text.hpp"
#include "cli/version.hpp"

int main(int argc, char** argv) {
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
  gridCommand
      ->add_option("--device", grid.device,
                   "OpenCL device: auto (first GPU, else CPU), cpu, gpu, or an index from "
                   "`penumbra devices`")
      ->capture_default_str();
  gridCommand->add_flag("--reference", grid.reference,
                        "Use the host reference estimator instead of the OpenCL kernel");
  gridCommand
      ->add_option("--reference-n", grid.referenceN,
                   "Reference: about N*N sample points per source face")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  // One name per --grid, so that `--grid a scene.yaml` does not swallow the scene.
  gridCommand
      ->add_option("--grid", grid.grids,
                   "Compute only this grid (repeat for several; default: all)")
      ->allow_extra_args(false);
  gridCommand->add_flag("-q,--quiet", grid.quiet, "No progress and no table; errors only");

  CLI::App* devicesCommand = app.add_subcommand("devices", penumbra::help::kDevices);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with status 0; every real usage error is status 1 (2 is
    // reserved for an invalid scene).
    const int status = app.exit(e);
    return status == 0 ? 0 : 1;
  }
  if (*gridCommand) return penumbra::runGridCommand(grid);
  if (*devicesCommand) return penumbra::runDevicesCommand();
  return 1;
}
