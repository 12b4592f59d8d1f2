// Rendered views with interreflected light: a pixel's E against the grid's total E at its
// point (Estimator, the final gather), the luminance as ρ/π times the total per channel, a
// ceiling lit by reflection only, and the field of interreflected light that interpolates within
// an element only (`penumbra render --direct-only` against the direct renderer: render_cli_test).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>
#include <numbers>

#include "illuminance/estimator.hpp"
#include "interval_bounds.hpp"
#include "radiosity/indirect_field.hpp"
#include "radiosity/radiosity_solver.hpp"
#include "render/renderer.hpp"
#include "sanitized_build.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;

Scene office() {
  return loadScene(PENUMBRA_SOURCE_DIR "/data/office.yaml");
}

// The grid's total E (Estimator: direct + final gather) at every pixel centre that shows a
// solid, by pixel index; NaN elsewhere.
std::vector<double> gridTotal(Renderer& renderer, Estimator& estimator, const View& view) {
  const std::vector<std::optional<SamplePoint>> visible = renderer.visiblePoints(view);
  std::vector<SamplePoint> points;
  for (const auto& p : visible)
    if (p) points.push_back(*p);
  const PointIlluminance e = estimator.illuminance(points);
  std::vector<double> byPixel(visible.size(), NAN);
  for (std::size_t i = 0, j = 0; i < visible.size(); ++i)
    if (visible[i]) byPixel[i] = e.total[j++];
  return byPixel;
}

struct Agreement {
  double worst = 0.0, mean = 0.0;
  std::size_t pixels = 0;
};

// |pixel E − grid E| relative to the grid's E, over the pixels that show a solid.
Agreement agreement(const RenderedView& rendered, const std::vector<double>& grid) {
  Agreement a;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (std::isnan(grid[i])) continue;
    const double d = std::abs(rendered.illuminance.values[i] - grid[i]) / grid[i];
    a.worst = std::max(a.worst, d);
    a.mean += d;
    ++a.pixels;
  }
  a.mean /= std::max<std::size_t>(a.pixels, 1);
  return a;
}

// Gathered at every pixel, the render's E is the grid's total E at the pixel's point: the same
// direct kernel and the same final gather over the same solved mesh, summed per channel in
// float (1e-5). By default the interreflected light comes from the field over the solved mesh
// (radiosity/indirect_field.hpp), interpolated within each element; the pixels stay within the
// mesh's own accuracy, 1e-3 of the total (docs/method.md, "Interreflection": the default mesh
// against the collocation reference), so the interpolation adds less error than the mesh
// already has; the gather is continuous across each face (kernel against the exact reference:
// tests/occlusion_test.cpp), so every pixel is compared. The sanitizer build renders a quarter
// of the pixels.
TEST(RenderedTotal, APixelEqualsTheGridsTotalAtItsPoint) {
  const Scene scene = office();
  Renderer renderer(cpuDevice(), scene, {}, MeshOptions{});
  EstimatorOptions options;
  options.device = "cpu";
  Estimator estimator(options, scene);
  for (const View& full : scene.views) {
    View view = full;
    view.width = kSanitizedBuild ? 160 : 320;
    view.height = kSanitizedBuild ? 90 : 180;
    const std::vector<double> grid = gridTotal(renderer, estimator, view);
    RenderOptions everywhere;
    everywhere.exactIndirect = true;
    const RenderedView exact = renderer.render(view, everywhere);
    const Agreement a = agreement(exact, grid);
    ASSERT_GT(a.pixels, grid.size() / 2);
    EXPECT_EQ(exact.stats.gatheredSamples, a.pixels);
    EXPECT_LE(a.worst, 1e-5) << view.name;
    const RenderedView fromField = renderer.render(view, RenderOptions{});
    const Agreement b = agreement(fromField, grid);
    EXPECT_LE(b.worst, 1e-3) << view.name;
    // The field's cost below one gather per pixel holds at 320 × 180, not at the sanitizer
    // build's quarter of the pixels, where the elements' triangles outnumber them.
    if (!kSanitizedBuild) {
      EXPECT_LT(fromField.stats.gatheredSamples, b.pixels) << view.name;
    }
    std::printf(
        "%s %d x %d: gathered everywhere worst %.2e; field (%zu points gathered for %zu pixels) "
        "worst %.2e, mean %.2e\n",
        view.name.c_str(), view.width, view.height, a.worst, fromField.stats.gatheredSamples,
        b.pixels, b.worst, b.mean);
    // Interval mode on the total: the field taken at the plan's exact samples and checked with
    // the direct light, against the field at every pixel (interval_bounds.hpp).
    const RenderedView sampled = renderer.render(view, RenderOptions{8, 1, {}});
    const IntervalErrors e = intervalErrors(fromField, sampled);
    std::printf("%s k = 8: exact share %.3f, worst %.4f %% of p99, %.4f %% per pixel\n",
                view.name.c_str(), sampled.stats.exactShare(), 100 * e.worst / e.p99,
                100 * e.worstRelative);
    EXPECT_LE(e.worst, 0.005 * e.p99) << view.name;
    EXPECT_LE(e.worstRelative, 0.01) << view.name;
    // And k = 8 interpolates: at 320 × 180 about half the samples are exact; at the sanitizer
    // build's 160 × 90 an interval spans twice the scene and the checks compute 73 % of them.
    if (!kSanitizedBuild) {
      EXPECT_LT(sampled.stats.exactShare(), 0.6) << view.name;
    }
  }
}

// L = ρ_c/π · (E_direct,c + E_indirect,c) per channel, so π·L_c/ρ_c is the channel's E and
// its photometric sum is the pixel's E, on grey and on coloured (oak) faces alike.
TEST(RenderedTotal, LuminanceIsReflectanceOverPiTimesTheTotalPerChannel) {
  const Scene scene = office();
  View view = scene.views.front();
  view.width = 160;
  view.height = 90;
  Renderer renderer(cpuDevice(), scene, {}, MeshOptions{});
  const RenderedView r = renderer.render(view, RenderOptions{});
  const std::vector<std::optional<SamplePoint>> visible = renderer.visiblePoints(view);
  double worst = 0.0;
  int coloured = 0;
  for (std::size_t i = 0; i < visible.size(); ++i) {
    if (!visible[i]) continue;
    const Solid& solid = scene.solids[visible[i]->solid];
    ASSERT_GE(solid.material, 0);
    const Vec3 rho = scene.materials[solid.material].reflectance;
    coloured += rho.x() != rho.z();
    Eigen::Vector3d e;
    for (int c = 0; c < 3; ++c) e[c] = std::numbers::pi * r.luminance.rgb[i * 3 + c] / rho[c];
    const double expected = r.illuminance.values[i];
    worst = std::max(worst, std::abs(photometric(e) - expected) / expected);
  }
  EXPECT_GT(coloured, 100);
  EXPECT_LE(worst, 1e-5);
}

// A closed room of one grey paint with a panel on the ceiling shining down: the ceiling gets
// no direct light at all (the panel's back faces it), so its E is all interreflected. The
// direct-only render shows it black (E = 0, the closed form); the total render shows it lit,
// with E equal to the grid's total at the same points and L = ρ·E/π.
TEST(RenderedTotal, ACeilingLitOnlyByReflectionIsTheGridsValue) {
  TempDir dir("penumbra-render-interreflection");
  std::ofstream(dir.path() / "room.yaml") << R"(penumbra: 1
materials: {paint: 0.6}
room: {size: [4, 3, 3], materials: {floor: paint, ceiling: paint, walls: paint}}
sources:
  - {name: panel, rect: {center: [2, 1.5, 2.99], size: [0.6, 0.6], normal: [0, 0, -1]}, flux: 3000}
views:
  - {name: up, eye: [2, 1.5, 1.2], target: [2.2, 1.6, 3], fov: 100, size: [96, 64]}
)";
  const Scene scene = loadScene(dir.path() / "room.yaml");
  const View& view = scene.views.front();
  Renderer direct(cpuDevice(), scene);
  Renderer total(cpuDevice(), scene, {}, MeshOptions{});
  const RenderedView d = direct.render(view, RenderOptions{});
  const RenderedView t = total.render(view, RenderOptions{});
  EstimatorOptions options;
  options.device = "cpu";
  Estimator estimator(options, scene);
  const std::vector<double> grid = gridTotal(total, estimator, view);
  const std::vector<std::optional<SamplePoint>> visible = total.visiblePoints(view);
  int ceiling = 0;
  double worst = 0.0, least = INFINITY;
  for (std::size_t i = 0; i < visible.size(); ++i) {
    if (!visible[i] || visible[i]->normal.z() > -0.5) continue;  // the ceiling faces down
    ++ceiling;
    EXPECT_EQ(d.illuminance.values[i], 0.0f);
    EXPECT_EQ(d.luminance.rgb[i * 3 + 1], 0.0f);
    least = std::min<double>(least, t.illuminance.values[i]);
    worst = std::max(worst, std::abs(t.illuminance.values[i] - grid[i]) / grid[i]);
    EXPECT_NEAR(t.luminance.rgb[i * 3 + 1], 0.6 / std::numbers::pi * t.illuminance.values[i],
                1e-6 * t.illuminance.values[i]);
  }
  EXPECT_GT(ceiling, 96 * 64 / 2);
  EXPECT_GT(least, 10.0);  // lx: every ceiling pixel is lit by reflection
  EXPECT_LE(worst, 1e-3);
  std::printf("ceiling: %d pixels, E from %.1f lx, worst relative difference to the grid %.2e\n",
              ceiling, least, worst);
}

}  // namespace
}  // namespace penumbra
