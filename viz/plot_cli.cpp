#include "viz/plot_cli.hpp"

#include <algorithm>
#include <charconv>
#include <map>
#include <string>
#include <vector>

#include "viz/plot_help.hpp"

namespace penumbra::viz {

namespace {

double parseLux(const std::string& text, const std::string& option) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || stop != end) {
    throw CLI::ValidationError(option, "'" + text + "' is not a number of lux");
  }
  return value;
}

std::pair<double, double> parseRange(const std::string& text) {
  const auto colon = text.find(':');
  if (colon == std::string::npos) {
    throw CLI::ValidationError("--range", "expected MIN:MAX in lx, for example 0:1000");
  }
  const double lo = parseLux(text.substr(0, colon), "--range");
  const double hi = parseLux(text.substr(colon + 1), "--range");
  if (!(hi > lo)) throw CLI::ValidationError("--range", "MAX must be above MIN");
  return {lo, hi};
}

// "100,200,500" → ascending, each once; "none" → no lines.
void parseLevels(const std::string& text, PlotOptions& options) {
  options.isolux.clear();
  options.noIsolux = text == "none";
  if (options.noIsolux) return;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const double level = parseLux(text.substr(start, comma - start), "--isolux");
    if (!(level > 0.0)) throw CLI::ValidationError("--isolux", "levels must be above 0 lx");
    options.isolux.push_back(level);
    start = comma + 1;
  }
  std::sort(options.isolux.begin(), options.isolux.end());
  options.isolux.erase(std::unique(options.isolux.begin(), options.isolux.end()),
                       options.isolux.end());
}

// The options `plot` and `grid --plot` share; each needs `needs` when given.
void addDrawingOptions(CLI::App& command, PlotOptions& options, CLI::Option* needs) {
  std::vector<CLI::Option*> added;
  added.push_back(
      command
          .add_option_function<std::string>(
              "--range",
              [&options](const std::string& text) { options.legend.range = parseRange(text); },
              "Legend from MIN to MAX lx (e.g. 0:1000), the same for every picture: variants "
              "compare colour for colour. Default: 0 to a round value at or above Emax")
          ->type_name("MIN:MAX"));
  added.push_back(command.add_flag("--log", options.legend.log,
                                   "Logarithmic legend (for daylight, where E spans decades)"));
  added.push_back(
      command
          .add_option_function<std::string>(
              "--isolux", [&options](const std::string& text) { parseLevels(text, options); },
              "Isolux levels in lx, comma-separated (e.g. 100,200,300,500,750), or none. "
              "Default: the 1-2-5 series between Emin and Emax")
          ->type_name("LX,LX,..."));
  added.push_back(
      command
          .add_option("--palette", options.legend.palette,
                      "Colours: viridis (perceptually uniform, fine in grey and for colour-blind "
                      "readers) or falsecolor (the look of Radiance's falsecolor)")
          ->transform(CLI::CheckedTransformer(
                          std::map<std::string, Palette>{{"viridis", Palette::Viridis},
                                                         {"falsecolor", Palette::FalseColor}},
                          CLI::ignore_case)
                          .description(""))
          ->type_name("viridis|falsecolor")
          ->default_str("viridis"));
  added.push_back(command
                      .add_option("--width", options.width,
                                  "Width of every PNG in px (the height follows the plan)")
                      ->capture_default_str()
                      ->check(CLI::Range(400, 8000).description(""))
                      ->type_name("PX"));
  added.push_back(command
                      .add_option("--isobands", options.isobands,
                                  "Also draw each planar grid as <grid>.svg: about N bands of E "
                                  "between isolux lines, as vector polygons")
                      ->check(CLI::Range(1, 64).description(""))
                      ->type_name("N"));
  added.push_back(command
                      .add_option("--surface-spacing", options.surfaceSpacing,
                                  "Distance between samples on the room's surfaces, m. Default: "
                                  "about 1/75 of the scene's size, rounded (0.1 m for an office)")
                      ->check(CLI::PositiveNumber)
                      ->type_name("M"));
  if (needs != nullptr) {
    for (CLI::Option* option : added) option->needs(needs);
  }
}

}  // namespace

CLI::App* addPlotCommand(CLI::App& app, PlotOptions& options) {
  CLI::App* command = app.add_subcommand("plot", help::kPlot);
  command->footer(help::kPlotFooter);
  command
      ->add_option("folder", options.folder,
                   "The output directory of `penumbra grid` (with summary.json)")
      ->required()
      ->check(CLI::ExistingDirectory);
  addDrawingOptions(*command, options, nullptr);
  command
      ->add_option("--device", options.device,
                   "OpenCL device for E on the room's surfaces: auto, cpu, gpu, or an index from "
                   "`penumbra devices`")
      ->capture_default_str();
  command
      ->add_option("--ugr-limit", options.ugrLimit,
                   "On the folder of `penumbra glare`: the EN 12464-1 limit UGR_L drawn on the UGR "
                   "maps (16, 19, 22, 25, 28)")
      ->capture_default_str()
      ->check(CLI::Range(5.0, 40.0));
  command->add_flag("-q,--quiet", options.quiet, "No progress and no list of files; errors only");
  return command;
}

CLI::Option* addPlotFlag(CLI::App& gridCommand, bool& plot, PlotOptions& options) {
  CLI::Option* flag = gridCommand.add_flag("--plot", plot, help::kPlotFlag);
  addDrawingOptions(gridCommand, options, flag);
  return flag;
}

}  // namespace penumbra::viz
