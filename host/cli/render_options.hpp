#pragma once
// The options of `penumbra render` (CLI11), kept out of main.cpp.
#include <cmath>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cli/display_options.hpp"
#include "cli/help_text.hpp"
#include "cli/option_checks.hpp"
#include "cli/render_command.hpp"

namespace penumbra::cli {

// 1, 4, 9, 16, ...: a side × side grid of samples in each pixel.
inline const CLI::Validator kSquareSampleCount(
    [](std::string& text) -> std::string {
      try {
        const int n = std::stoi(text);
        const int side = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
        if (n >= 1 && side * side == n) return {};
      } catch (const std::exception&) {
      }
      return "samples per pixel must be a square number (1, 4, 9, 16, ...), got " + text;
    },
    "1|4|9|16|...");

inline CLI::App* addRenderCommand(CLI::App& app, RenderCommandOptions& options,
                                  std::vector<std::string>& settings, bool& noCulling) {
  CLI::App* command = app.add_subcommand("render", help::kRender);
  command->footer(help::kRenderFooter);
  command->add_option("scene", options.scene, "Scene file (YAML, scene format v1)")->required();
  command->add_option("-o,--output", options.output, "Output directory (created if missing)")
      ->required();
  command
      ->add_option("--view", options.views,
                   "Render only this view (repeat for several; default: all)")
      ->allow_extra_args(false);
  command
      ->add_option("--interval", options.interval,
                   "k: exact illuminance every k pixels along a row, interpolated between where "
                   "the light is smooth (never across a face or shadow boundary; midpoint and "
                   "curvature checked to 0.1 %); 1 = every pixel")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--spp", options.spp,
                   "Samples per pixel for anti-aliased edges: 1, 4 (2 x 2), 9 (3 x 3), ...")
      ->capture_default_str()
      ->check(kSquareSampleCount);
  addDeviceOption(*command, options.estimator.device);
  addInterreflectionOptions(*command, options.estimator);
  command->add_flag(
      "--no-culling", noCulling,
      "Test every occluder at every pixel (no shadow volumes): slower, the same image");
  command
      ->add_option("--set", settings,
                   "Give a scene parameter a value other than its default: NAME=VALUE (repeat)")
      ->allow_extra_args(false)
      ->check(kParameterAssignment);
  addDisplayOptions(*command, options.display);
  command
      ->add_option("--isobands", options.isobands,
                   "Also draw each view as <view>.svg: every face split into about N bands of E "
                   "between isolux lines, vector polygons drawn back to front")
      ->check(CLI::Range(1, 64))
      ->type_name("N");
  command->add_flag("-q,--quiet", options.quiet, "No progress and no summary; errors only");
  return command;
}

}  // namespace penumbra::cli
