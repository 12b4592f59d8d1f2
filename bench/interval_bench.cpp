// Interval sampling against the exact render on the example office, or another scene
// (docs/render.md, "Interval sampling"): each view rendered with k = 1 and with k, the luminance Y
// (Rec. 709 weights of the RGB image, cd/m²) compared pixel by pixel. Prints per view the largest
// |Y_k − Y_1| over the 99th percentile of Y_1 (all pixels), the largest relative error among the
// pixels above 1 % of that percentile, the share of samples computed exactly, the render's wall
// and CPU time (each the best of R; no files written; CPU time, of every thread, is steadier than
// wall time on a shared machine), the speed-up k = 1 over k from those best times and as the
// median of R pairs rendered in turn (pair_x, pair_cpu: each pair meets the same load), the direct
// light's time at k = 1 (direct1_s) and the interreflected light's at k (indirectk_s), and below
// each view the stages of the best k = 1 and k renders (RenderStats: visibility, the direct light
// with the interval plan, the interreflected light, shading; wall) and the pixels of the two
// largest errors. With interreflection the renderer's field of interreflected light
// (radiosity/indirect_field.hpp) is shared by every render of the scene: first1_s is the view's
// first full-size render (k = 1, gathering what the field lacks for it), field_nodes and field_s
// what the field has gathered and spent so far (the warm-up included); the best-of-R renders find
// it complete.
//   usage: interval_bench [--device cpu|gpu|<index>] [--size WxH] [--k K] [--repeat R]
//                         [--direct-only] [--view NAME] [--scene FILE]
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <optional>
#include <string>
#include <vector>

#include "bench/median.hpp"
#include "cl/device.hpp"
#include "memory/heap_settings.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"

namespace {

using namespace penumbra;

std::vector<double> luminanceY(const RgbImage& image) {
  std::vector<double> y(static_cast<std::size_t>(image.width) * image.height);
  for (std::size_t i = 0; i < y.size(); ++i)
    y[i] =
        0.2126 * image.rgb[i * 3] + 0.7152 * image.rgb[i * 3 + 1] + 0.0722 * image.rgb[i * 3 + 2];
  return y;
}

struct Timed {
  RenderedView view;
  double seconds = 1e30;     // wall
  double cpuSeconds = 1e30;  // CPU time of the process, every thread (PoCL's included)
};

// One render's time, and the render itself.
Timed timed(Renderer& renderer, const View& view, int k) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpuStart = std::clock();
  Timed t;
  t.view = renderer.render(view, RenderOptions{k, 1, {}});
  t.cpuSeconds = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return t;
}

// Keeps the faster render (wall) and the least CPU time.
void keepBest(Timed& best, Timed&& t) {
  best.cpuSeconds = std::min(best.cpuSeconds, t.cpuSeconds);
  if (t.seconds < best.seconds) {
    best.seconds = t.seconds;
    best.view = std::move(t.view);
  }
}

}  // namespace

int main(int argc, char** argv) {
  keepFreedBlocksInTheHeap();  // as the command does: what these renders cost there
  std::string deviceSpec = "auto", only, sceneFile = PENUMBRA_SOURCE_DIR "/data/office.yaml";
  int width = 1280, height = 720, k = 8, repeat = 2;
  bool directOnly = false;
  for (int i = 1; i < argc; ++i) {
    const bool more = i + 1 < argc;
    if (!std::strcmp(argv[i], "--direct-only")) directOnly = true;
    if (!more) continue;
    if (!std::strcmp(argv[i], "--device"))
      deviceSpec = argv[++i];
    else if (!std::strcmp(argv[i], "--view"))
      only = argv[++i];
    else if (!std::strcmp(argv[i], "--scene"))
      sceneFile = argv[++i];
    else if (!std::strcmp(argv[i], "--k"))
      k = std::stoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--repeat"))
      repeat = std::stoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--size"))
      std::sscanf(argv[++i], "%dx%d", &width, &height);
  }
  const Scene scene = loadScene(sceneFile);
  compute::Device device = compute::Device::select(deviceSpec);
  Renderer renderer(device, scene, EngineOptions{},
                    directOnly ? std::nullopt : std::optional<MeshOptions>(MeshOptions{}));
  fmt::print("{} {} x {}, {}, k = 1 against k = {}, on {}, best of {}\n", sceneFile, width, height,
             directOnly ? "direct only" : "total (direct + interreflected)", k, device.info().name,
             repeat);
  fmt::print(
      "{:<12} {:>9} {:>11} {:>7} {:>8} {:>9} {:>9} {:>9} {:>8} {:>8} {:>8} {:>8} {:>8} {:>8} "
      "{:>9} {:>11} {:>11} {:>8} {:>9}\n",
      "view", "p99_cdm2", "max_of_p99%", "pixel%", "exact_%", "first1_s", "render1_s", "renderk_s",
      "speed-up", "pair_x", "cpu1_s", "cpuk_s", "cpu_x", "pair_cpu", "direct1_s", "indirectk_s",
      "field_nodes", "field_s", "gatheredk");
  for (const View& full : scene.views) {
    if (!only.empty() && full.name != only) continue;
    View view = full;
    view.width = width;
    view.height = height;
    renderer.render(View{view.name, view.eye, view.target, view.up, view.fovDegrees, 64, 36},
                    RenderOptions{1, 1, {}});  // warm-up: kernels built and cached
    const Timed first = timed(renderer, view, 1);
    // k = 1 and k rendered in turn, so that each pair meets the same load on a shared machine.
    Timed exact, sampled;
    std::vector<double> pairRatio, pairCpuRatio;
    for (int r = 0; r < repeat; ++r) {
      Timed one = timed(renderer, view, 1), some = timed(renderer, view, k);
      pairRatio.push_back(one.seconds / some.seconds);
      pairCpuRatio.push_back(one.cpuSeconds / some.cpuSeconds);
      keepBest(exact, std::move(one));
      keepBest(sampled, std::move(some));
    }
    const std::vector<double> y1 = luminanceY(exact.view.luminance),
                              yk = luminanceY(sampled.view.luminance);
    std::vector<double> sorted = y1;
    const std::size_t at = static_cast<std::size_t>(0.99 * (sorted.size() - 1));
    std::nth_element(sorted.begin(), sorted.begin() + at, sorted.end());
    const double p99 = sorted[at];
    double worst = 0, worstRelative = 0;
    std::size_t worstAt = 0, worstRelativeAt = 0;
    for (std::size_t i = 0; i < y1.size(); ++i) {
      const double d = std::abs(yk[i] - y1[i]);
      if (d > worst) {
        worst = d;
        worstAt = i;
      }
      if (y1[i] > 0.01 * p99 && d / y1[i] > worstRelative) {
        worstRelative = d / y1[i];
        worstRelativeAt = i;
      }
    }
    const IndirectFieldStats* field = renderer.indirectField();
    fmt::print(
        "{:<12} {:>9.2f} {:>11.4f} {:>7.4f} {:>8.1f} {:>9.3f} {:>9.3f} {:>9.3f} {:>8.2f} {:>8.2f} "
        "{:>8.3f} {:>8.3f} {:>8.2f} {:>8.2f} {:>9.3f} {:>11.3f} {:>11} {:>8.3f} {:>9}\n",
        view.name, p99, 100 * worst / p99, 100 * worstRelative,
        100 * sampled.view.stats.exactShare(), first.seconds, exact.seconds, sampled.seconds,
        exact.seconds / sampled.seconds, bench::median(pairRatio), exact.cpuSeconds,
        sampled.cpuSeconds, exact.cpuSeconds / sampled.cpuSeconds, bench::median(pairCpuRatio),
        exact.view.stats.illuminanceSeconds, sampled.view.stats.indirectSeconds,
        field ? field->nodes : 0, field ? field->seconds : 0.0, sampled.view.stats.gatheredSamples);
    for (const auto& [interval, timed] : {std::pair{1, &exact}, std::pair{k, &sampled}}) {
      const RenderStats& stats = timed->view.stats;
      fmt::print(
          "  k = {}: visibility {:.3f} s, direct {:.3f} s, interreflected {:.3f} s, "
          "shading {:.3f} s (wall)\n",
          interval, stats.visibilitySeconds, stats.illuminanceSeconds, stats.indirectSeconds,
          stats.shadingSeconds);
    }
    // Where the two worst errors are, to look at them (pixel x, y from the top left).
    for (const auto& [what, i] :
         {std::pair{"of p99", worstAt}, std::pair{"per pixel", worstRelativeAt}})
      fmt::print("  worst {} at pixel ({}, {}): Y {:.2f} cd/m2 (k = 1), {:.2f} (k = {})\n", what,
                 i % width, i / width, y1[i], yk[i], k);
  }
  return 0;
}
