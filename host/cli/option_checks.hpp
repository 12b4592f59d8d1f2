#pragma once
// Options that penumbra's subcommands share (CLI11), and the checks and conversions of their
// values, so that a bad value is a usage error (exit status 1) naming it, before any work starts.
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "illuminance/estimator.hpp"
#include "scene/parameters.hpp"
#include "study/render_exposure.hpp"

namespace penumbra::cli {

// A check from a parser that throws std::invalid_argument saying what is wrong.
template <typename Parse>
CLI::Validator checkedBy(Parse parse, const std::string& name) {
  return CLI::Validator(
      [parse](std::string& text) -> std::string {
        try {
          parse(text);
          return {};
        } catch (const std::invalid_argument& e) {
          return e.what();
        }
      },
      name);
}

// NAME=VALUE, as `--set window_width_m=1.6` takes it.
inline const CLI::Validator kParameterAssignment =
    checkedBy([](const std::string& text) { parseParameterAssignment(text); }, "NAME=VALUE");

// `sweep --exposure`: a white in cd/m², auto-first or auto-all.
inline const CLI::Validator kStudyExposure = checkedBy(
    [](const std::string& text) { parseRenderExposure(text); }, "CDM2|auto-first|auto-all");

// --device: the OpenCL device a command computes on.
inline void addDeviceOption(CLI::App& command, std::string& device) {
  command
      .add_option("--device", device,
                  "OpenCL device: auto (first GPU, else CPU), cpu, gpu, or an index from "
                  "`penumbra devices`")
      ->capture_default_str();
}

// --direct-only, --element-size: whether E and the images include the interreflected light,
// and on which mesh (`grid`, `sweep` and `render`).
inline void addInterreflectionOptions(CLI::App& command, EstimatorOptions& options) {
  command.add_flag("!--direct-only", options.interreflection,
                   "Direct light only: leave out the light the room's surfaces reflect (E is then "
                   "the direct illuminance, as without interreflection)");
  command
      .add_option("--element-size", options.mesh.elementSize,
                  "Interreflection: the longest side of a surface element in m; smaller is more "
                  "exact and slower (docs/method.md, \"Interreflection\")")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  command
      .add_option("--link-error", options.mesh.linkError,
                  "Interreflection: the error bound of a hierarchical link, relative to the E of "
                  "a hemisphere of unit luminance; 0 computes every element pair (the dense "
                  "transfer; a mesh of more than 8000 elements takes links at 2e-4 instead) "
                  "(docs/method.md, \"Hierarchical transfer\")")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
}

// --device, --reference, --reference-n, --direct-only, --element-size: how `grid` and `sweep`
// compute E.
inline void addEstimatorOptions(CLI::App& command, EstimatorOptions& options) {
  addDeviceOption(command, options.device);
  command.add_flag("--reference", options.reference,
                   "Use the host reference estimator instead of the OpenCL kernel (direct light "
                   "only)");
  command
      .add_option("--reference-n", options.referenceN,
                  "Reference: about N*N sample points per source face")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  addInterreflectionOptions(command, options);
}

inline ParameterValues parameterAssignments(const std::vector<std::string>& texts) {
  ParameterValues values;
  for (const std::string& text : texts) values.push_back(parseParameterAssignment(text));
  return values;
}

}  // namespace penumbra::cli
