#pragma once
// `penumbra grid`: scene in, illuminance files out. Kept free of CLI11 so that the parsing
// (main.cpp) and the work (here) stay separate.
#include <filesystem>
#include <string>
#include <vector>

#include "scene/parameters.hpp"

namespace penumbra {

struct GridOptions {
  std::filesystem::path scene;
  std::filesystem::path output;
  std::string device = "auto";     // "auto", "cpu", "gpu" or an index from `penumbra devices`
  bool reference = false;          // the host reference instead of the OpenCL kernel
  int referenceN = 64;             // ~n² sub-elements per source face
  bool culling = true;             // shadow-volume culling; --no-culling runs the plain path
  std::vector<std::string> grids;  // only these grids; all when empty
  ParameterValues parameters;      // --set: replace these defaults of the scene's parameters
  bool quiet = false;
};

// Exit status: 0 done; 1 error (device, output, options); 2 the scene is invalid. Nothing is
// written unless everything succeeded. Messages go to stderr, the table to stdout.
int runGridCommand(const GridOptions& options);

}  // namespace penumbra
