#pragma once
// `penumbra glare SCENE -o DIR`: the UGR of every observer of the scene along each of its lines
// of sight (docs/glare.md).
#include <filesystem>

#include "illuminance/estimator.hpp"
#include "scene/parameters.hpp"

namespace penumbra {

struct GlareOptions {
  std::filesystem::path scene;
  std::filesystem::path output;
  EstimatorOptions estimator;  // device and interreflection: the background luminance
  ParameterValues parameters;
  bool quiet = false;
};

// Exit status 0; 2 for an invalid scene (file:line: key: message); 1 for any other error. Nothing
// is written unless everything is.
int runGlareCommand(const GlareOptions& options);

}  // namespace penumbra
