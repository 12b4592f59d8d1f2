// Rendered views of a daylit room with the sun (data/office-sun.yaml): a pixel's E against the
// grid's E at its point (the kernel's sky sources cut at the point's height and the host's sun,
// against the render's sky and sun on the host), direct and with interreflection (the sun's
// reflected light included); what the window shows (the sky, the ground and the sun's disk at
// their luminance times the glazing's τ, against closed forms written here).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/angles.hpp"
#include "illuminance/estimator.hpp"
#include "illuminance/sunlight.hpp"
#include "render/camera.hpp"
#include "render/renderer.hpp"
#include "sanitized_build.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;

Scene officeSun() {
  return loadScene(PENUMBRA_SOURCE_DIR "/data/office-sun.yaml");
}

// The scene's views at a size the test affords (the sanitizer build: a quarter of the pixels).
std::vector<View> smallViews(const Scene& scene) {
  std::vector<View> views;
  for (View view : scene.views) {
    view.width = kSanitizedBuild ? 48 : 96;
    view.height = kSanitizedBuild ? 27 : 54;
    views.push_back(view);
  }
  return views;
}

struct PixelComparison {
  double worst = 0.0;        // |render − grid| / scale over the pixels that show a solid
  std::size_t pixels = 0;    // that show a solid
  std::size_t sunlit = 0;    // of those, with direct sunlight
  std::size_t gathered = 0;  // the render's gathered samples (with interreflection)
};

// The render's E at every pixel that shows a solid against the Estimator's at the same point,
// relative to the grid's E, or to `floor` (lx) where E is below it: the kernel's precision is
// stated against the light a point would receive unoccluded, not against the little that
// passes where walls and reveals shade it.
PixelComparison compare(Renderer& renderer, Estimator& estimator, const View& view,
                        const RenderOptions& options, double floor) {
  const std::vector<std::optional<SamplePoint>> visible = renderer.visiblePoints(view);
  std::vector<SamplePoint> points;
  std::vector<std::size_t> pixelOf;
  for (std::size_t i = 0; i < visible.size(); ++i)
    if (visible[i]) {
      points.push_back(*visible[i]);
      pixelOf.push_back(i);
    }
  const PointIlluminance grid = estimator.illuminance(points);
  const RenderedView rendered = renderer.render(view, options);
  PixelComparison c;
  c.pixels = points.size();
  c.gathered = rendered.stats.gatheredSamples;
  for (std::size_t j = 0; j < points.size(); ++j) {
    const double e = rendered.illuminance.values[pixelOf[j]];
    c.worst = std::max(c.worst, std::abs(e - grid.total[j]) / std::max(grid.total[j], floor));
    c.sunlit += grid.sun[j] > 0.0;
  }
  return c;
}

// A tenth of what the glazing passes of the outdoor horizontal illuminance, τ·E_h/10 (lx): more
// than the sky and the ground give a point in the room near the window's own wall, where the
// reveals hide most of the window (a few lx), less than most points get.
double shadeFloor(const Scene& scene) {
  return 0.1 * scene.room->openings.front().transmittance * scene.sky->horizontalIlluminance;
}

// Direct light: the grid takes the overcast sky and the ground through the window as the
// kernel's sources (float), the render takes them on the host (double, past every solid), both
// take the sun on the host. They agree to the kernel's float precision (1e-5 of E), in the sun
// patch, its penumbra and the shade alike; every pixel is exact at k = 1.
TEST(RenderedDaylight, APixelEqualsTheGridsDirectDaylightAtItsPoint) {
  const Scene scene = officeSun();
  Renderer renderer(cpuDevice(), scene);
  EstimatorOptions options;
  options.device = "cpu";
  options.interreflection = false;
  Estimator estimator(options, scene);
  for (const View& view : smallViews(scene)) {
    const PixelComparison c =
        compare(renderer, estimator, view, RenderOptions{}, shadeFloor(scene));
    EXPECT_GT(c.pixels, view.width * view.height / 2u) << view.name;
    EXPECT_GT(c.sunlit, c.pixels / 50) << view.name << ": the sun patch is in the view";
    EXPECT_LE(c.worst, 1e-5) << view.name;
    std::printf("%s %d x %d, direct: %zu pixels (%zu sunlit), worst %.2e\n", view.name.c_str(),
                view.width, view.height, c.pixels, c.sunlit, c.worst);
  }
}

// With interreflection, gathered at every pixel: the render's total (sky, ground, sun, and the
// room's reflection of all three) is the grid's total at the point, to the same float precision.
// A coarse mesh: the assertion is an identity of the two paths on any mesh.
TEST(RenderedDaylight, WithInterreflectionAPixelEqualsTheGridsTotal) {
  const Scene scene = officeSun();
  MeshOptions mesh;
  mesh.elementSize = 1.0;
  mesh.refinementLevels = 0;
  Renderer renderer(cpuDevice(), scene, {}, mesh);
  EstimatorOptions options;
  options.device = "cpu";
  options.mesh = mesh;
  Estimator estimator(options, scene);
  const View view = smallViews(scene).front();
  RenderOptions everywhere;
  everywhere.exactIndirect = true;
  const PixelComparison c = compare(renderer, estimator, view, everywhere, shadeFloor(scene));
  EXPECT_EQ(c.gathered, c.pixels);
  EXPECT_GT(c.sunlit, c.pixels / 50);
  EXPECT_LE(c.worst, 1e-5);
  std::printf("%s %d x %d, total: %zu pixels (%zu sunlit), worst %.2e\n", view.name.c_str(),
              view.width, view.height, c.pixels, c.sunlit, c.worst);
}

// Looking out of the window (τ = 0.7) from inside the room: every pixel that meets no solid sees
// the sky or the ground through the glazing, at τ·L_z(1 + 2 sin α)/3 above the horizon
// (L_z = 9 E_h/(7π)) and τ·ρ_g·E_h/π below it; aimed at the sun, the pixel at the sun's centre
// shows τ times the luminance of a disk of 0.53° that gives E_dn: the scene's sun is a regular
// 32-gon inscribed in the disk, so L = E_dn / (16 sin(2π/32) tan² r) to O(r²) = 2e-5.
TEST(RenderedDaylight, TheWindowShowsTheSkyTheGroundAndTheSunThroughItsGlazing) {
  const Scene scene = officeSun();
  ASSERT_TRUE(scene.sky && scene.sun && scene.room);
  const double tau = scene.room->openings.front().transmittance;
  const double eh = scene.sky->horizontalIlluminance;
  const double zenith = 9.0 * eh / (7.0 * std::numbers::pi);
  const double ground = scene.sky->groundReflectance * eh / std::numbers::pi;
  Renderer renderer(cpuDevice(), scene);

  View out;
  out.eye = Vec3(3.0, 1.5, 1.65);  // m: in the room, facing the window's centre
  out.target = Vec3(3.0, 0.0, 1.65);
  out.fovDegrees = 90.0;
  out.width = 64;
  out.height = 48;
  const RenderedView r = renderer.render(out, RenderOptions{});
  const Camera camera = Camera::forView(out, 1);
  int sky = 0, below = 0;
  double worst = 0.0;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * out.width + x;
      if (r.faces.ids[i] != FaceIdImage::kNoSurface) continue;
      const Vec3 d = camera.direction(x, y).normalized();
      const double expected = tau * (d.z() >= 0.0 ? zenith * (1.0 + 2.0 * d.z()) / 3.0 : ground);
      (d.z() >= 0.0 ? sky : below) += 1;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(r.luminance.rgb[i * 3 + c] - expected) / expected);
    }
  EXPECT_GT(sky, 100);
  EXPECT_GT(below, 100);
  EXPECT_LE(worst, 1e-6);  // float pixels

  // 1.2 m from the window's centre on the inside, on the line to the sun.
  View atSun = out;
  const Vec3 sun = scene.sun->direction.normalized();
  atSun.eye = Vec3(3.0, 0.0, 1.65) - 1.2 * sun;
  atSun.target = atSun.eye + sun;
  atSun.fovDegrees = 1.0;  // the disk, 0.53°, covers the middle half of the row
  atSun.width = 33;
  atSun.height = 33;
  const RenderedView s = renderer.render(atSun, RenderOptions{});
  const std::size_t centre = 16 * 33 + 16;
  ASSERT_EQ(s.faces.ids[centre], FaceIdImage::kNoSurface) << "the sun is seen through the window";
  const double r0 = 0.5 * kSunDiameterDegrees * kRadiansPerDegree;
  const double polygon = 0.5 * kSunPolygonSides *
                         std::sin(2.0 * std::numbers::pi / kSunPolygonSides) * std::tan(r0) *
                         std::tan(r0);
  const double expectedSun = tau * scene.sun->directNormalIlluminance / polygon;
  EXPECT_NEAR(s.luminance.rgb[centre * 3 + 1] / expectedSun, 1.0, 1e-4);
  // The corner pixels (0.7° off the centre) show the sky beside the sun.
  EXPECT_LT(s.luminance.rgb[1], 1e-3 * expectedSun);
  std::printf("sky %d and ground %d pixels within %.1e; the sun %.4g cd/m² (expected %.4g)\n", sky,
              below, worst, s.luminance.rgb[centre * 3 + 1], expectedSun);
}

}  // namespace
}  // namespace penumbra
