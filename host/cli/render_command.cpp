#include "cli/render_command.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>

#include "cl/device.hpp"
#include "cli/exit_status.hpp"
#include "cli/interreflection_notes.hpp"
#include "cli/render_progress.hpp"
#include "cli/scene_warnings.hpp"
#include "cli/version.hpp"
#include "grid/scene_grids.hpp"
#include "output/render_files.hpp"
#include "output/result_files.hpp"
#include "output/staged_directory.hpp"
#include "render/renderer.hpp"
#include "scene/scene_loader.hpp"
#include "tonemap/tone_map.hpp"

namespace penumbra {
namespace {

using Clock = std::chrono::steady_clock;

std::vector<const View*> selectViews(const Scene& scene, const RenderCommandOptions& options) {
  if (scene.views.empty()) {
    throw std::runtime_error(fmt::format(
        "{} has no views to render; add one under 'views:' (docs/scene-format.md, \"Views\"), "
        "e.g. views: [{{name: from-door, eye: [0.5, 3.5, 1.6], target: [4, 1, 1.2]}}]",
        options.scene.string()));
  }
  std::vector<const View*> views;
  for (const View& view : scene.views)
    if (options.views.empty() ||
        std::find(options.views.begin(), options.views.end(), view.name) != options.views.end())
      views.push_back(&view);
  for (const std::string& name : options.views) {
    if (std::none_of(views.begin(), views.end(), [&](const View* v) { return v->name == name; })) {
      std::string known;
      for (const View& view : scene.views) known += (known.empty() ? "" : ", ") + view.name;
      throw std::runtime_error(fmt::format("{} has no view '{}'; its views are: {}",
                                           options.scene.string(), name, known));
    }
  }
  return views;
}

int run(const RenderCommandOptions& options) {
  const auto start = Clock::now();
  checkOutputTarget(options.output);
  const Scene scene = loadScene(options.scene, options.parameters);
  if (!options.quiet) printSceneWarnings(scene);
  const std::vector<const View*> views = selectViews(scene, options);

  const EstimatorOptions& estimator = options.estimator;
  compute::Device device = compute::Device::select(estimator.device);
  const compute::DeviceInfo& info = device.info();
  RenderReport report;
  report.version = kVersion;
  report.sceneFile = options.scene;
  report.parameters = scene.parameters;
  report.device = fmt::format("{} ({}, {})", info.name, info.platform, info.type);
  report.interval = options.interval;
  report.spp = options.spp;
  report.display = displayMethodName(options.display.method);
  report.displayLuminance = options.display.displayLuminance;
  report.ambient = options.display.ambient;
  if (!options.quiet) {
    fmt::print(stderr, "penumbra: {} on {}\n", options.scene.string(), report.device);
  }
  Renderer renderer(device, scene, EngineOptions{estimator.culling},
                    estimator.interreflection ? std::optional(estimator.mesh) : std::nullopt);
  if (const InterreflectionReport* solved = renderer.interreflection())
    report.interreflection = *solved;
  if (!options.quiet) {
    warnAboutBlackSolids(report.interreflection);
    noteLinksPastDenseLimit(report.interreflection, estimator.mesh);
  }
  report.luminaires = luminaireReports(scene);
  for (const View* view : views) {
    RenderProgress progress(!options.quiet, view->name, view->height);
    RenderOptions renderOptions{options.interval, options.spp,
                                [&](double fraction) { progress.update(fraction); }};
    RenderedView rendered = renderer.render(*view, renderOptions);
    progress.finish();
    ToneMapStats toneMapStats;
    DisplayImage display =
        toneMap(rendered.luminance, rendered.faces, options.display, &toneMapStats);
    report.views.push_back({std::move(rendered), std::move(display), toneMapStats});
  }
  report.totalSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  writeRenders(report, options.output, [&](const std::filesystem::path& dir) {
    if (options.isobands <= 0 || !options.vectorDrawing) return;
    for (const RenderReport::ViewFiles& files : report.views) {
      if (!options.quiet)
        fmt::print(stderr, "penumbra: view {}: iso-bands\n", files.rendered.view.name);
      options.vectorDrawing(scene, files.rendered, device, options.isobands, dir);
    }
  });
  if (!options.quiet) {
    for (const RenderReport::ViewFiles& files : report.views) {
      const RenderedView& r = files.rendered;
      const RenderStats& s = r.stats;
      fmt::print(
          "{:<16} {} × {} px, {} sample(s)/px, exact {:.1f} % of surface samples, "
          "visibility {:.2f} s, illuminance {:.2f} s, shading {:.2f} s{}\n",
          r.view.name, r.view.width, r.view.height, options.spp, 100.0 * s.exactShare(),
          s.visibilitySeconds, s.illuminanceSeconds, s.shadingSeconds,
          report.interreflection ? fmt::format(", interreflection {:.2f} s ({} points gathered)",
                                               s.indirectSeconds, s.gatheredSamples)
                                 : std::string());
    }
    fmt::print("light: {}\n",
               illuminanceMeaning(report.interreflection.has_value(), report.luminaires));
    fmt::print("renders in {}\n", normalizedTarget(options.output).string());
  }
  return 0;
}

}  // namespace

int runRenderCommand(const RenderCommandOptions& options) {
  return cli::reportingErrors([&] { return run(options); });
}

}  // namespace penumbra
