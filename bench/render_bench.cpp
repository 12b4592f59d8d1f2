// Rendering the example office: a 1280 × 720 view on the OpenCL device for interval
// k = 1, 4 and 8: seconds per render, Mpixel·sources/s, the share of exact samples, and the share
// of time in visibility, illuminance, shading and output (the tone map and the files of a view).
// Also the same visible points evaluated as one plain grid, the floor the render's illuminance part
// can reach. Prints a table and one JSON line per k.
//   usage: render_bench [--device cpu|gpu|<index>] [--view NAME] [--size WxH] [--repeat R]
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>

#include "cl/device.hpp"
#include "engine/illuminance_engine.hpp"
#include "memory/heap_settings.hpp"
#include "output/render_files.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"
#include "tonemap/tone_map.hpp"

namespace {

using namespace penumbra;
using Clock = std::chrono::steady_clock;

double seconds(auto&& f) {
  const auto start = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  keepFreedBlocksInTheHeap();  // as the command does: what these renders cost there
  std::string deviceSpec = "auto", viewName = "from-door";
  int width = 1280, height = 720, repeat = 2;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--device")) deviceSpec = argv[i + 1];
    if (!std::strcmp(argv[i], "--view")) viewName = argv[i + 1];
    if (!std::strcmp(argv[i], "--repeat")) repeat = std::stoi(argv[i + 1]);
    if (!std::strcmp(argv[i], "--size")) std::sscanf(argv[i + 1], "%dx%d", &width, &height);
  }
  const Scene scene = loadScene(PENUMBRA_SOURCE_DIR "/data/office.yaml");
  View view;
  for (const View& v : scene.views)
    if (v.name == viewName) view = v;
  view.width = width;
  view.height = height;
  compute::Device device = compute::Device::select(deviceSpec);
  std::unique_ptr<Renderer> renderer;
  const double setup = seconds([&] { renderer = std::make_unique<Renderer>(device, scene); });
  renderer->render(View{view.name, view.eye, view.target, view.up, view.fovDegrees, 64, 36},
                   RenderOptions{1, 1, {}});  // warm-up: kernels built and cached
  const int sources = static_cast<int>(scene.sources.size());
  fmt::print("office view {} {} x {} on {} ({} sources), set-up {:.2f} s, best of {}\n", view.name,
             width, height, device.info().name, sources, setup, repeat);

  // The floor: the same points as one grid, straight through the illuminance engine.
  std::vector<SamplePoint> points;
  for (const auto& p : renderer->visiblePoints(view))
    if (p) points.push_back(*p);
  IlluminanceEngine engine(device, scene);
  double gridBest = 1e30;
  for (int r = 0; r < repeat; ++r)
    gridBest = std::min(gridBest, seconds([&] { engine.evaluate(points, true); }));
  fmt::print("the visible points as one grid: {} points in {:.3f} s ({:.2f} µs/point)\n",
             points.size(), gridBest, 1e6 * gridBest / points.size());

  fmt::print("{:>3} {:>9} {:>12} {:>8} {:>11} {:>12} {:>9} {:>8}\n", "k", "render_s", "Mpx·src/s",
             "exact_%", "visibility%", "illuminance%", "shading%", "output%");
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / fmt::format("penumbra-render-bench-{}", getpid());
  for (int k : {1, 4, 8}) {
    RenderedView best;
    double bestSeconds = 1e30;
    for (int r = 0; r < repeat; ++r) {
      RenderedView rendered;
      const double s = seconds([&] { rendered = renderer->render(view, RenderOptions{k, 1, {}}); });
      if (s < bestSeconds) {
        bestSeconds = s;
        best = std::move(rendered);
      }
    }
    RenderReport report;
    report.interval = k;
    report.display = "constraint";
    const RenderStats stats = best.stats;
    const double output = seconds([&] {
      ToneMapStats toneMapStats;
      DisplayImage display = toneMap(best.luminance, best.faces, ToneMapOptions{}, &toneMapStats);
      report.views.push_back({std::move(best), std::move(display), toneMapStats});
      writeRenders(report, out);
    });
    const double total = bestSeconds + output;
    const double mpxSources = 1e-6 * width * height * sources / bestSeconds;
    fmt::print("{:>3} {:>9.3f} {:>12.2f} {:>8.1f} {:>11.1f} {:>12.1f} {:>9.1f} {:>8.1f}\n", k,
               bestSeconds, mpxSources, 100.0 * stats.exactShare(),
               100.0 * stats.visibilitySeconds / total, 100.0 * stats.illuminanceSeconds / total,
               100.0 * stats.shadingSeconds / total, 100.0 * output / total);
    std::cout << nlohmann::json{{"k", k},
                                {"width", width},
                                {"height", height},
                                {"render_s", bestSeconds},
                                {"output_s", output},
                                {"mpixel_sources_per_s", mpxSources},
                                {"exact_share", stats.exactShare()},
                                {"visibility_s", stats.visibilitySeconds},
                                {"illuminance_s", stats.illuminanceSeconds},
                                {"shading_s", stats.shadingSeconds}}
                     .dump()
              << "\n";
  }
  std::filesystem::remove_all(out);
  return 0;
}
