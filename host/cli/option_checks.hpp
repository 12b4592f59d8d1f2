#pragma once
// Options that penumbra's subcommands share (CLI11), and the checks and conversions of their
// values, so that a bad value is a usage error (exit status 1) naming it, before any work starts.
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "scene/parameters.hpp"

namespace penumbra::cli {

// NAME=VALUE, as `--set window_width_m=1.6` takes it.
inline const CLI::Validator kParameterAssignment(
    [](std::string& text) -> std::string {
      try {
        parseParameterAssignment(text);
        return {};
      } catch (const std::invalid_argument& e) {
        return e.what();
      }
    },
    "NAME=VALUE");

// --device, --reference, --reference-n: how `grid` and `sweep` compute E.
inline void addEstimatorOptions(CLI::App& command, std::string& device, bool& reference,
                                int& referenceN) {
  command
      .add_option("--device", device,
                  "OpenCL device: auto (first GPU, else CPU), cpu, gpu, or an index from "
                  "`penumbra devices`")
      ->capture_default_str();
  command.add_flag("--reference", reference,
                   "Use the host reference estimator instead of the OpenCL kernel");
  command
      .add_option("--reference-n", referenceN, "Reference: about N*N sample points per source face")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
}

inline ParameterValues parameterAssignments(const std::vector<std::string>& texts) {
  ParameterValues values;
  for (const std::string& text : texts) values.push_back(parseParameterAssignment(text));
  return values;
}

}  // namespace penumbra::cli
