#pragma once
// The display options shared by `penumbra tonemap` and `penumbra render`: one function, so that
// both commands take the same flags with the same defaults and checks.
#include <array>
#include <string>

#include <CLI/CLI.hpp>

#include "tonemap/tone_map_options.hpp"

namespace penumbra::cli {

// The display the PNG is encoded for (docs/tonemap.md, "The display model"): also on `sweep`,
// whose renders take no other display option. Returns the two options.
inline std::array<CLI::Option*, 2> addTargetDisplayOptions(CLI::App& command,
                                                           ToneMapOptions& options) {
  CLI::Option* luminance =
      command
          .add_option(
              "--display-luminance", options.displayLuminance,
              "The target display's white in cd/m2: the PNG holds the sRGB code values that "
              "show the tone map's luminances on it")
          ->capture_default_str()
          ->check(CLI::Range(1.0, 1e5))
          ->type_name("CDM2");
  CLI::Option* ambient =
      command
          .add_option("--ambient", options.ambient,
                      "Illuminance on the display's screen from the room around it, lx: its "
                      "reflection (1 %) lifts the display's black, and the tone map works above it")
          ->capture_default_str()
          ->check(CLI::Range(0.0, 1e5))
          ->type_name("LX");
  return {luminance, ambient};
}

inline void addDisplayOptions(CLI::App& command, ToneMapOptions& options) {
  // By name only (a plain enum option would also take 0, 1, 2 and print them in --help).
  CLI::Option* display =
      command
          .add_option_function<std::string>(
              "--display",
              [&options](const std::string& name) { options.method = displayMethodFromName(name); },
              "How HDR luminance becomes display values: constraint (Fang's constraint hierarchy, "
              "default), linear (thesis eq. 4.2), clip (auto exposure, cut)")
          ->check(CLI::IsMember({"clip", "linear", "constraint"}, CLI::ignore_case))
          ->type_name("clip|linear|constraint");
  command
      .add_option_function<double>(
          "--exposure",
          [&options](double white) {
            options.method = DisplayMethod::Clip;
            options.white = white;
          },
          "A fixed exposure: this luminance in cd/m2 is white (the clip display, cut to black "
          "and white), so that pictures compare: the same cd/m2 is the same pixel value in each")
      ->check(CLI::PositiveNumber)
      ->excludes(display)
      ->type_name("CDM2");
  addTargetDisplayOptions(command, options);
  command
      .add_option("--black", options.black,
                  "The display's black as a fraction of its white (LowerBound)")
      ->capture_default_str()
      ->check(CLI::Range(1e-4, 0.5));
  command
      .add_option("--strong", options.strong,
                  "Weight of the edge rows: compressed log ratio (constraint only)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      .add_option("--medium", options.medium,
                  "Weight of the rows inside a region (attenuated log gradient)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      .add_option("--weak", options.weak,
                  "Weight of the rows that pull V to the exposure curve (Space 3)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      .add_option_function<std::string>(
          "--vertices",
          [&options](const std::string& name) { options.vertices = vertexLatticeFromName(name); },
          "Where the constraint map's unknowns lie: levels (default: each region shown as one "
          "curve of its own luminance, knots at most 5 % apart; no halos) or image (the thesis's "
          "mesh of pixels, a gain that may change across a region)")
      ->check(CLI::IsMember({"levels", "image"}, CLI::ignore_case))
      ->type_name("levels|image");
  command
      .add_option("--lattice", options.lattice,
                  "--vertices image: largest spacing of a region's vertices, in pixels")
      ->capture_default_str()
      ->check(CLI::Range(1, 256));
}

}  // namespace penumbra::cli
