#pragma once
// `penumbra tonemap`: an HDR render and its face ids in, a PNG and its statistics out. Kept free
// of CLI11, as the other commands are.
#include <filesystem>

#include "tonemap/tone_map_options.hpp"

namespace penumbra {

struct ToneMapCommandOptions {
  std::filesystem::path input;   // <view>.exr (linear RGB, cd/m²)
  std::filesystem::path faces;   // <view>.faceid.exr; empty: beside the input under that name
  std::filesystem::path output;  // <view>.png; the statistics go to <view>.tonemap.json
  ToneMapOptions display;
  bool verbose = false;
};

// <view>.exr → <view>.faceid.exr, the name `penumbra render` gives it.
std::filesystem::path facesBeside(const std::filesystem::path& input);

// Exit status 0 done, 1 error (files, sizes, options). Messages go to stderr.
int runToneMapCommand(const ToneMapCommandOptions& options);

}  // namespace penumbra
