#pragma once
// `penumbra grid`: scene in, illuminance files out. Kept free of CLI11 so that the parsing
// (main.cpp) and the work (here) stay separate.
#include <filesystem>
#include <string>
#include <vector>

#include "illuminance/estimator.hpp"
#include "scene/parameters.hpp"

namespace penumbra {

struct GridOptions {
  std::filesystem::path scene;
  std::filesystem::path output;
  // --device, --reference, --reference-n, --no-culling, --direct-only, --element-size
  EstimatorOptions estimator;
  std::vector<std::string> grids;  // only these grids; all when empty
  ParameterValues parameters;      // --set: replace these defaults of the scene's parameters
  bool quiet = false;
};

// Exit status: 0 done; 1 error (device, output, options); 2 the scene is invalid. Nothing is
// written unless everything succeeded. Messages go to stderr, the table to stdout.
int runGridCommand(const GridOptions& options);

}  // namespace penumbra
