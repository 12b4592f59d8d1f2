// The sun's light reflected by the room (radiosity/interreflection.hpp): what it adds to E, that it
// scales with the sun, and that the flux the sun brings onto the room's surfaces is the flux that
// passes the window. The daylight factor leaving it out is SunInGrids' test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "engine/illuminance_engine.hpp"
#include "illuminance/estimator.hpp"
#include "illuminance/sunlight.hpp"
#include "radiosity/interreflection.hpp"
#include "radiosity/sun_on_elements.hpp"
#include "sanitized_build.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"

namespace penumbra {
namespace {

using testing::cpuDevice;
using testing::kSanitizedBuild;

Scene officeSun() {
  return loadScene(PENUMBRA_SOURCE_DIR "/data/office-sun.yaml");
}

// The identities below hold on any mesh. The host's sunlight on the cells of the elements a
// patch edge crosses is most of their cost, and under ASan it runs many times slower: the
// sanitizer build takes the office's faces in elements unrefined (far fewer crossed ones).
EstimatorOptions cpuOptions() {
  EstimatorOptions options;
  options.device = "cpu";
  if (kSanitizedBuild) options.mesh.refinementLevels = 0;
  return options;
}

// The points of every grid of the scene.
std::vector<SamplePoint> allGridPoints(const Scene& scene) {
  std::vector<SamplePoint> points;
  for (const CalculationGrid& grid : scene.grids)
    for (std::size_t i = 0; i < grid.size(); ++i)
      points.push_back({grid.position(i), grid.normal(i), -1});
  return points;
}

// The systems with and without the sun share their mesh and the sky's right-hand side, so the
// difference is the sun's light to rounding; twice the sun's illuminance scales every value of
// its solve by two exactly. So with each element's luminance uniform in the final gather, and
// with the default gather, linear across each element: the sun's part takes slope shares of its
// own (SlopeGather::shares), the same in every run and for any E_dn, and the sky's part the
// same shares with or without the sun.
TEST(SunInterreflected, AddsTheDirectSunlightAndItsReflectionAndScalesWithTheSun) {
  const Scene sunny = officeSun();
  ASSERT_TRUE(sunny.sun && sunny.sun->aboveHorizon());
  Scene overcast = sunny;
  overcast.sun.reset();
  Scene brighter = sunny;
  brighter.sun->directNormalIlluminance *= 2.0;
  const std::vector<SamplePoint> points = allGridPoints(sunny);
  for (const bool linearGather : {false, true}) {
    EstimatorOptions options = cpuOptions();
    options.mesh.linearGather = linearGather;
    Estimator withSun(options, sunny), withoutSun(options, overcast), twiceSun(options, brighter);
    const PointIlluminance a = withSun.illuminance(points);
    const PointIlluminance b = withoutSun.illuminance(points);
    const PointIlluminance c = twiceSun.illuminance(points);
    ASSERT_EQ(a.sunReflected.size(), points.size());
    ASSERT_EQ(c.sunReflected.size(), points.size());
    EXPECT_TRUE(b.sunReflected.empty());
    double sunMean = 0.0, reflectedMean = 0.0, overcastMean = 0.0, worstSum = 0.0, worstTwice = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const auto at = [&] { return ::testing::Message() << points[i].position.transpose(); };
      // Every point sees the ceiling, which the sun patch lights.
      EXPECT_GT(a.sunReflected[i], 0.0) << at();
      EXPECT_NEAR(a.total[i] - b.total[i], a.sun[i] + a.sunReflected[i], 1e-12 * a.total[i])
          << at();
      EXPECT_NEAR(a.direct[i] - b.direct[i], a.sun[i], 1e-12 * a.total[i]) << at();
      EXPECT_NEAR(c.sunReflected[i], 2.0 * a.sunReflected[i], 1e-12 * c.total[i]) << at();
      worstSum = std::max(
          worstSum, std::abs(a.total[i] - b.total[i] - a.sun[i] - a.sunReflected[i]) / a.total[i]);
      worstTwice =
          std::max(worstTwice, std::abs(c.sunReflected[i] - 2.0 * a.sunReflected[i]) / c.total[i]);
      sunMean += a.sun[i], reflectedMean += a.sunReflected[i], overcastMean += b.total[i];
    }
    const double n = static_cast<double>(points.size());
    std::printf(
        "  office-sun, %s gather, %zu grid points: mean E without the sun %.1f lx, direct "
        "sunlight %.1f lx, reflected sunlight %.1f lx; sun's parts against the difference of the "
        "runs %.1e, twice the sun %.1e of E\n",
        linearGather ? "linear" : "uniform", points.size(), overcastMean / n, sunMean / n,
        reflectedMean / n, worstSum, worstTwice);
  }
}

// The sun's flux onto the mesh (the element-average direct sunlight times the area) is the flux
// through the window's glazing, E_dn · cos θ · τ · w · h (cos θ = d·n, d the beam's direction, n
// the wall's inward normal). Of it, the beam that passes the inner rectangle of the 0.2 m wall
// too, (w − t|d_x/d_y|)(h − t|d_z/d_y|) of the window, lands in the room (on the floor and a desk
// here: every face lit has a material) and the rest on the reveals. The 0.53° disk changes these
// by less than 1e-4, the bound held (the overlap is linear in each shift across the disk); what
// remains is the average over the elements the patch's edges cross (sun_on_elements.hpp: the
// midpoint rule on cells there, printed at three cell counts).
TEST(SunInterreflected, TheSunsFluxOntoTheRoomIsTheFluxThroughTheWindow) {
  const Scene scene = officeSun();
  IlluminanceEngine direct(cpuDevice(), scene);
  const HostDirectLight sun = [&](std::span<const SamplePoint> points) {
    return sunlight(scene, points);
  };
  Interreflection solved(cpuDevice(), scene, direct, {}, {}, nullptr, HostLight{{}, sun});
  const SurfaceMesh& mesh = solved.mesh();
  ASSERT_EQ(static_cast<std::size_t>(solved.sunDirect().size()), mesh.elements.size());

  // data/office-sun.yaml: the window in wall y0 (the room on +y), 2.0 × 1.5 m, τ = 0.7, t = 0.2 m.
  const double width = 2.0, height = 1.5, wall = 0.2, transmittance = 0.7;
  const Vec3 beam = -scene.sun->direction.normalized();
  ASSERT_GT(beam.y(), 0.0);
  const double through = scene.sun->directNormalIlluminance * beam.y() * transmittance;  // lx
  const double passing = (width - wall * std::abs(beam.x() / beam.y())) *
                         (height - wall * std::abs(beam.z() / beam.y()));  // m²
  const double expectedRoom = through * passing;
  const double expectedReveals = through * (width * height - passing);

  // The element averages as the solver takes them (kSunCellsPerSide), and with other cell counts
  // for the trend (not in the sanitizer build, where the host's sunlight runs many times slower).
  const std::vector<double> atNodes =
      kSanitizedBuild ? std::vector<double>(mesh.nodes.size()) : sunlight(scene, mesh.nodes);
  const Eigen::Map<const Eigen::VectorXd> nodeSun(atNodes.data(),
                                                  static_cast<Eigen::Index>(atNodes.size()));
  const std::vector<int> cellCounts =
      kSanitizedBuild
          ? std::vector<int>{kSunCellsPerSide}
          : std::vector<int>{kSunCellsPerSide / 4, kSunCellsPerSide, 2 * kSunCellsPerSide};
  for (int cells : cellCounts) {
    const Eigen::VectorXd average = cells == kSunCellsPerSide
                                        ? solved.sunDirect()
                                        : sunElementAverage(scene, sun, mesh, nodeSun, cells);
    double room = 0.0, reveals = 0.0;  // lm
    for (std::size_t i = 0; i < mesh.elements.size(); ++i) {
      const double flux = average[static_cast<Eigen::Index>(i)] * mesh.elements[i].area;
      (mesh.elements[i].polygon.centroid().y() < 0.0 ? reveals : room) += flux;
    }
    const double roomError = std::abs(room - expectedRoom) / expectedRoom;
    const double revealsError = std::abs(reveals - expectedReveals) / expectedReveals;
    std::printf(
        "  %d × %d cells: the sun's flux onto the room %.1f lm (through both rectangles %.1f lm, "
        "%.2e), onto the reveals %.1f lm (%.1f lm, %.2e)\n",
        cells, cells, room, expectedRoom, roomError, reveals, expectedReveals, revealsError);
    if (cells == kSunCellsPerSide) {
      EXPECT_LT(roomError, 1e-4);
      EXPECT_LT(revealsError, 1e-4);
    }
  }
}

}  // namespace
}  // namespace penumbra
