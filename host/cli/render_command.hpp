#pragma once
// `penumbra render`: scene and views in, HDR images and AOVs out (output/render_files.hpp).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cl/device.hpp"
#include "illuminance/estimator.hpp"
#include "render/renderer.hpp"
#include "scene/parameters.hpp"
#include "scene/scene.hpp"
#include "tonemap/tone_map_options.hpp"

namespace penumbra {

struct RenderCommandOptions {
  std::filesystem::path scene;
  std::filesystem::path output;
  std::vector<std::string> views;  // only these; all when empty
  int interval = 1;                // exact every k pixels along a row
  int spp = 1;                     // samples per pixel (a square)
  // The device, culling, and whether the images include the interreflected light (and on
  // which mesh); the reference options do not apply to renders.
  EstimatorOptions estimator;
  ParameterValues parameters;
  ToneMapOptions display;  // how <view>.png is made from the HDR image
  int isobands = 0;        // > 0: also <view>.svg and <view>.isobands.png, by `vectorDrawing`
  // Draws the iso-bands of a rendered view into a folder (viz/, wired by main.cpp: host/ never
  // includes viz/).
  std::function<void(const Scene&, const RenderedView&, compute::Device&, int bands,
                     const std::filesystem::path& folder)>
      vectorDrawing;
  bool quiet = false;
};

// Exit status as `penumbra grid`: 0 done; 1 error; 2 invalid scene. Nothing is written unless
// every view rendered.
int runRenderCommand(const RenderCommandOptions& options);

}  // namespace penumbra
