// The daylight factor with interreflection against an independent reference: a closed box room
// with one window under the CIE overcast sky, solved by collocation in double
// (box_room_radiosity.hpp) with the light through the window integrated by quadrature
// (window_sky_quadrature.hpp), none of it product code.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "box_room_radiosity.hpp"
#include "illuminance/estimator.hpp"
#include "sanitized_build.hpp"
#include "scene/scene_loader.hpp"
#include "window_sky_quadrature.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;

// A 4 × 3 × 3 m room of ρ = 0.5 with a 2 × 1.5 m window in the wall y = 0 (x 1..3 m, z 0.75..2.25
// m), whose edges fall on the reference's patch grid at n = 8, 12, 16, 24 and 32 patches a face.
// The walls are 0.5 mm thick, so that the reveals, which the reference leaves out, hold 0.0035 m²
// of the room's 66 m²: lit by the sky, they add about 3e-4 to the work plane's DF at 2 mm, more
// than what the linear gather leaves at 0.25 m elements.
constexpr double kEh = 10000.0;  // lx
const WallWindow kWindow{1.0, 3.0, 0.75, 2.25, 0.0005, 1.0};

Scene windowRoom() {
  return parseScene(
      "penumbra: 1\n"
      "sky: {model: cie-overcast, horizontal_illuminance_lx: 10000, ground_reflectance: 0.2}\n"
      "materials: {paint: 0.5}\n"
      "room:\n"
      "  size: [4, 3, 3]\n"
      "  wall_thickness: 0.0005\n"
      "  materials: {floor: paint, ceiling: paint, walls: paint}\n"
      "  openings:\n"
      "    - {name: w1, wall: y0, x: 1.0, z: 0.75, width: 2.0, height: 1.5}\n",
      "window-room.yaml");
}

// The daylight factor on the work plane (0.8 m), in %, total and direct (sky and ground seen
// through the window), by the product with elements of `size` (m) and by the reference's limit.
TEST(DaylightFactorInterreflected, AClosedRoomWithOneWindowMatchesCollocation) {
  const Scene scene = windowRoom();
  ASSERT_TRUE(scene.sky.has_value());
  std::vector<SamplePoint> points;
  for (double x : {0.5, 2.0, 3.5})
    for (double y : {0.5, 1.5, 2.5}) points.push_back({Vec3(x, y, 0.8), Vec3::UnitZ(), -1});

  BoxRoomCase box;
  box.size = V3(4.0, 3.0, 3.0);
  box.reflectance = 0.5;
  const BoxRoomLighting daylight{
      [&](const V3& p, const V3& n) { return windowSkyQuadrature(*scene.sky, kWindow, p, n, 48); },
      {{kWindow.x0, kWindow.x1, kWindow.z0, kWindow.z1}}};
  // The sanitizer build checks the code path on a coarse reference (its dense LU runs slowly
  // under ASan); the Release build holds the numbers.
  const std::array<int, 3> n = kSanitizedBuild ? std::array{8, 12, 16} : std::array{16, 24, 32};
  std::array<std::vector<double>, 3> byN;
  for (std::size_t k = 0; k < n.size(); ++k) {
    const BoxRoomReference reference(box, n[k], daylight);
    for (const SamplePoint& p : points)
      byN[k].push_back(100.0 * reference.totalIlluminance(p.position, p.normal) / kEh);
  }
  std::vector<double> limit, direct;
  for (std::size_t i = 0; i < points.size(); ++i) {
    limit.push_back(collocationLimit(byN[0][i], byN[1][i], byN[2][i]));
    direct.push_back(100.0 * daylight.direct(points[i].position, points[i].normal) / kEh);
  }

  for (double linkError : {0.0, MeshOptions::kDefaultLinkError}) {
    double previous = INFINITY;
    for (double size : {0.5, 0.25}) {
      EstimatorOptions options;
      options.device = "cpu";
      options.mesh.elementSize = size;
      options.mesh.linkError = linkError;
      Estimator estimator(options, scene);
      const PointIlluminance e = estimator.illuminance(points);
      ASSERT_EQ(e.direct.size(), points.size());
      double worst = 0.0, worstDirect = 0.0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const double df = 100.0 * e.total[i] / kEh, dfDirect = 100.0 * e.direct[i] / kEh;
        worst = std::max(worst, std::abs(df - limit[i]) / limit[i]);
        worstDirect = std::max(worstDirect, std::abs(dfDirect - direct[i]) / direct[i]);
        // The direct part is exact (the kernel's float rounding).
        EXPECT_NEAR(dfDirect, direct[i], 1e-5 * direct[i]) << points[i].position.transpose();
        EXPECT_GT(df, dfDirect) << points[i].position.transpose();
      }
      std::printf(
          "  link error %g, element size %.2f m: worst |DF - reference| / reference %.2e (direct "
          "part %.2e)\n",
          linkError, size, worst, worstDirect);
      if (kSanitizedBuild) continue;
      if (size == 0.25) {
        EXPECT_LT(worst, 1e-3) << linkError;
      }
      EXPECT_LT(worst, previous) << linkError;
      previous = worst;
    }
  }
  for (std::size_t i = 0; i < points.size(); ++i)
    std::printf(
        "  (%.1f, %.1f): DF %.4f %% (direct %.4f %%), reference n = %d/%d/%d: %.4f %.4f %.4f\n",
        points[i].position.x(), points[i].position.y(), limit[i], direct[i], n[0], n[1], n[2],
        byN[0][i], byN[1][i], byN[2][i]);
}

}  // namespace
}  // namespace penumbra
