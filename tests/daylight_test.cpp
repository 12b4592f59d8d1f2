// Daylight through openings (scene/daylight.hpp, docs/method.md "Daylight"): the uniform and CIE
// overcast skies and the ground, seen through a room's openings, against closed forms and an
// independent quadrature written here; the opening's transmittance; the daylight factor figures.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "engine/daylight_evaluation.hpp"
#include "engine/illuminance_engine.hpp"
#include "geometry/tolerance.hpp"
#include "grid/grid_evaluation.hpp"
#include "grid/grid_metrics.hpp"
#include "grid/run_report.hpp"
#include "illuminance/estimator.hpp"
#include "output/grid_rows.hpp"
#include "output/summary_table.hpp"
#include "reference/exact_illuminance.hpp"
#include "scene/daylight.hpp"
#include "scene/scene_loader.hpp"
#include "scene_errors.hpp"
#include "test_device.hpp"
#include "window_sky_quadrature.hpp"

namespace penumbra {
namespace {

using testing::cpuDevice;
using testing::sceneErrorOf;

constexpr double kPi = std::numbers::pi;

// E at each point from the scene's sky and ground, exact in double: each point with its own
// height's daylight scene.
std::vector<double> exactDaylight(const Scene& scene, const std::vector<SamplePoint>& points) {
  return estimateByGroup(scene, points, [](const Scene& lit, std::span<const SamplePoint> p) {
    return exactIlluminance(lit, p).front();
  });
}

std::vector<double> kernelDaylight(const Scene& scene, const std::vector<SamplePoint>& points,
                                   EngineOptions options = {}) {
  IlluminanceEngine engine(cpuDevice(), scene, options);
  return evaluateDaylight(engine, scene, points).illuminance;
}

// ---- the unobstructed sky: E_h = π·L (uniform), 7π·L_z/9 (overcast)

// A scene whose only opening is a horizontal square skylight of half-side `half` at height 1 m,
// emitting downwards, over a point at the origin facing up: the point sees the sky through all of
// it. Its solid angle misses the hemisphere by the directions within atan(1/half) of the
// horizon, where the overcast sky's (1 + 2 sin α) cos θ and the uniform sky's cos θ vanish as
// (1/half)² and faster: at half = 10⁴ the deficit is below 1e-8 of E_h.
Scene skylightScene(SkyModel model, double half) {
  Scene scene;
  const double h = 1.0;
  // Counter-clockwise about −z (the emission direction): clockwise seen from above.
  ConvexPolygon square({{-half, -half, h}, {-half, half, h}, {half, half, h}, {half, -half, h}});
  Room room;
  room.size = Vec3(1.0, 1.0, 1.0);
  room.openings.push_back(Opening{"roof", "z1", 1.0, square, square});
  scene.room = room;
  scene.sky = Sky{model, 10000.0, 0.2};
  return scene;
}

TEST(DaylightSky, UnobstructedHorizontalIlluminanceIsEh) {
  const std::vector<SamplePoint> up = {{Vec3::Zero(), Vec3::UnitZ(), -1}};
  for (SkyModel model : {SkyModel::Uniform, SkyModel::CieOvercast}) {
    const Scene scene = skylightScene(model, 1e4);
    const Sky& sky = *scene.sky;
    // The closed forms the sky's luminance comes from, checked on their own: ∫ L cos θ dω over
    // the hemisphere.
    const double closedForm = model == SkyModel::Uniform ? kPi * sky.zenithLuminance()
                                                         : 7.0 * kPi * sky.zenithLuminance() / 9.0;
    EXPECT_NEAR(closedForm, sky.horizontalIlluminance, 1e-12 * sky.horizontalIlluminance);
    const double e = exactDaylight(scene, up).front();
    std::printf("  %s sky, unobstructed: E = %.9f lx for E_h = %.0f lx (%.2e relative)\n",
                model == SkyModel::Uniform ? "uniform" : "overcast", e, sky.horizontalIlluminance,
                std::abs(e - sky.horizontalIlluminance) / sky.horizontalIlluminance);
    EXPECT_NEAR(e, sky.horizontalIlluminance, 1e-6 * sky.horizontalIlluminance);
  }
}

// ---- a window in a black room against a quadrature written here

// The office's window: wall y0 (the room side y = 0, the outside y = −0.2), x 2..4 m, z 0.9..2.4 m.
constexpr double kX0 = 2.0, kX1 = 4.0, kZ0 = 0.9, kZ1 = 2.4, kWall = 0.2;

std::string roomYaml(const std::string& sky, double transmittance) {
  return "penumbra: 1\n" + sky +
         "room:\n"
         "  size: [6, 4, 3]\n"
         "  wall_thickness: 0.2\n"
         "  openings:\n"
         "    - {name: w1, wall: y0, x: 2.0, z: 0.9, width: 2.0, height: 1.5, transmittance: " +
         std::to_string(transmittance) + "}\n";
}

Scene roomScene(const std::string& model, double transmittance = 1.0) {
  return parseScene(roomYaml("sky: {model: " + model +
                                 ", horizontal_illuminance_lx: 10000, ground_reflectance: 0.2}\n",
                             transmittance),
                    "daylight.yaml");
}

// E at P (normal n) from the sky and ground through the window, by the definition
// (window_sky_quadrature.hpp: the part of the outer rectangle P sees through the room-side one).
double quadratureE(const Sky& sky, double transmittance, const SamplePoint& point) {
  return testing::windowSkyQuadrature(sky, {kX0, kX1, kZ0, kZ1, kWall, transmittance},
                                      point.position, point.normal);
}

// Points in front of the window, near its edges, below its sill (sky only) and above its head
// (facing the window, ground only), upward and vertical.
std::vector<SamplePoint> windowPoints() {
  const Vec3 up = Vec3::UnitZ(), facing = -Vec3::UnitY(), side = Vec3::UnitX();
  return {
      {Vec3(3.0, 1.0, 0.8), up, -1},        // the work plane in front
      {Vec3(2.05, 0.3, 0.8), up, -1},       // near the window's left edge
      {Vec3(5.5, 2.0, 0.8), up, -1},        // far to the side
      {Vec3(3.0, 0.4, 0.5), facing, -1},    // below the sill, facing it: sky only
      {Vec3(3.0, 0.6, 2.7), facing, -1},    // above the head, facing it: ground only
      {Vec3(3.0, 1.5, 1.6), facing, -1},    // mid-height: sky above, ground below
      {Vec3(3.95, 0.05, 2.3), facing, -1},  // near the head and a jamb
      {Vec3(1.0, 1.0, 1.2), side, -1},      // a vertical plane across the window
  };
}

TEST(DaylightWindow, MatchesAQuadratureOfTheSkyAndGroundOverTheVisibleOpening) {
  for (const std::string model : {"cie-overcast", "uniform"}) {
    const Scene scene = roomScene(model);
    const std::vector<SamplePoint> points = windowPoints();
    const std::vector<double> exact = exactDaylight(scene, points);
    const std::vector<double> kernel = kernelDaylight(scene, points);
    double worstExact = 0.0, worstKernel = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double q = quadratureE(*scene.sky, 1.0, points[i]);
      ASSERT_GT(q, 0.0) << points[i].position.transpose();
      worstExact = std::max(worstExact, std::abs(exact[i] - q) / q);
      worstKernel = std::max(worstKernel, std::abs(kernel[i] - q) / q);
      EXPECT_NEAR(exact[i], q, 1e-9 * q) << model << " at " << points[i].position.transpose();
      EXPECT_NEAR(kernel[i], q, 1e-5 * q) << model << " at " << points[i].position.transpose();
    }
    std::printf("  %s: largest |E − quadrature| / quadrature: host reference %.2e, kernel %.2e\n",
                model.c_str(), worstExact, worstKernel);
  }
}

TEST(DaylightWindow, EveryKernelPathMatchesTheHostReference) {
  const Scene scene = roomScene("cie-overcast");
  const std::vector<SamplePoint> points = windowPoints();
  const std::vector<double> exact = exactDaylight(scene, points);
  const EngineOptions paths[] = {{}, {true, true, false}, {true, false, true}, {false, true, true}};
  for (const EngineOptions& options : paths) {
    const std::vector<double> kernel = kernelDaylight(scene, points, options);
    for (std::size_t i = 0; i < points.size(); ++i)
      EXPECT_NEAR(kernel[i], exact[i], Tolerance::kKernelRelative * exact[i])
          << "culling " << options.culling << ", apertures " << options.apertures << ", lanes "
          << options.vectorPenumbra << " at " << points[i].position.transpose();
  }
}

// Points on the floor (on its solid) and up a wall across the window's height, in one call: many
// height groups, some with an empty sky or ground face, whose per-source rows (what the
// interreflection reads) must be zero, not left unwritten.
TEST(DaylightWindow, PointsAtManyHeightsMatchTheHostReferenceInTotalAndPerSource) {
  const Scene scene = roomScene("cie-overcast");
  ASSERT_EQ(scene.solids[0].name, "room.floor");
  std::vector<SamplePoint> points;
  for (double x : {0.4, 2.5, 4.87, 5.5})
    for (double y : {0.37, 1.5, 3.5}) points.push_back({Vec3(x, y, 0.0), Vec3::UnitZ(), 0});
  for (int k = 0; k < 60; ++k)
    points.push_back({Vec3(6.0, 1.0 + 0.01 * k, 0.05 * k + 0.01), -Vec3::UnitX(), -1});
  const std::vector<double> exact = exactDaylight(scene, points);
  {
    IlluminanceEngine engine(cpuDevice(), scene);
    const IlluminanceResult r = evaluateDaylight(engine, scene, points, true);
    for (std::size_t i = 0; i < points.size(); ++i)
      EXPECT_NEAR(r.illuminance[i], exact[i], Tolerance::kKernelRelative * exact[i])
          << "bySource at " << points[i].position.transpose();
  }
  const EngineOptions paths[] = {{}, {true, true, false}, {true, false, true}, {false, true, true}};
  for (const EngineOptions& options : paths) {
    const std::vector<double> kernel = kernelDaylight(scene, points, options);
    for (std::size_t i = 0; i < points.size(); ++i)
      EXPECT_NEAR(kernel[i], exact[i], Tolerance::kKernelRelative * exact[i])
          << "culling " << options.culling << ", apertures " << options.apertures << ", lanes "
          << options.vectorPenumbra << " at " << points[i].position.transpose();
  }
}

TEST(DaylightWindow, AboveTheHeadAPointSeesOnlyGroundThroughIt) {
  const Scene scene = roomScene("cie-overcast");
  // Facing the window from above its head, the point looks down through it: ground only.
  const SamplePoint high{Vec3(3.0, 0.4, 2.7), -Vec3::UnitY(), -1};
  const Scene lit = daylightScene(scene, high.position.z());
  ASSERT_EQ(lit.sources.size(), 2u);
  EXPECT_TRUE(lit.sources[0].faces.empty());  // the sky: none of the window is above P
  EXPECT_NEAR(lit.sources[1].luminance, 0.2 * 10000.0 / kPi, 1e-9);  // the ground: ρ_g·E_h/π
  // That ground alone, a uniform rectangle: E = L · (the visible window's Lambert integral).
  Scene groundOnly = lit;
  groundOnly.sources.erase(groundOnly.sources.begin());
  groundOnly.sky.reset();
  const double e = exactDaylight(scene, {high}).front();
  EXPECT_GT(e, 0.0);
  EXPECT_NEAR(e, exactIlluminance(groundOnly, std::vector<SamplePoint>{high}).front().front(),
              1e-12 * e);
  // Below the sill a point looks up through the window: sky only.
  const Scene low = daylightScene(scene, 0.5);
  EXPECT_FALSE(low.sources[0].faces.empty());
  EXPECT_TRUE(low.sources[1].faces.empty());
  // An upward point above the head has the whole window below its horizon.
  const SamplePoint up{Vec3(3.0, 0.4, 2.7), Vec3::UnitZ(), -1};
  EXPECT_EQ(exactDaylight(scene, {up}).front(), 0.0);
}

// ---- with interreflection

// A uniform sky over a ground of reflectance 1 has one luminance, E_h/π, above and below the
// horizon: the window is then an `opening:` source of that luminance, and every node of the
// interreflection mesh, whatever its height group, must receive what it receives from that
// source. So the total E (direct and interreflected) of both scenes agrees, on a work plane
// and on a vertical grid, to the kernel's float rounding. The mesh is left unrefined so that
// both runs solve on the same elements (refinement looks at each light source separately).
TEST(DaylightInterreflection, AUniformSkyOverAWhiteGroundIsAnOpeningSourceOfItsLuminance) {
  const std::string room =
      "materials: {white: 0.8, grey: 0.4}\n"
      "room:\n"
      "  size: [6, 4, 3]\n"
      "  materials: {floor: grey, ceiling: white, walls: white}\n"
      "  openings:\n"
      "    - {name: w1, wall: y0, x: 2.0, z: 0.9, width: 2.0, height: 1.5, transmittance: 0.7}\n";
  const Scene sky = parseScene(
      "penumbra: 1\nsky: {model: uniform, horizontal_illuminance_lx: 10000, ground_reflectance: "
      "1}\n" +
          room,
      "sky.yaml");
  const Scene source =
      parseScene("penumbra: 1\n" + room + "sources:\n  - {name: w1-sky, opening: w1, luminance: " +
                     std::to_string(10000.0 / kPi) + "}\n",
                 "source.yaml");
  std::vector<SamplePoint> points;
  for (double x : {0.7, 3.0, 5.3})
    for (double y : {0.6, 2.0, 3.4}) points.push_back({Vec3(x, y, 0.85), Vec3::UnitZ(), -1});
  for (double z : {0.3, 1.1, 1.65, 2.2, 2.8})
    points.push_back({Vec3(3.0, 3.0, z), -Vec3::UnitY(), -1});
  EstimatorOptions options;
  options.device = "cpu";
  options.mesh.refinementLevels = 0;
  Estimator fromSky(options, sky), fromSource(options, source);
  const PointIlluminance a = fromSky.illuminance(points), b = fromSource.illuminance(points);
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_GT(b.total[i], b.direct[i]) << points[i].position.transpose();  // light came back
    worst = std::max(worst, std::abs(a.total[i] - b.total[i]) / b.total[i]);
    EXPECT_NEAR(a.total[i], b.total[i], 1e-5 * b.total[i]) << points[i].position.transpose();
    EXPECT_NEAR(a.direct[i], b.direct[i], 1e-5 * b.direct[i]) << points[i].position.transpose();
  }
  std::printf("  uniform sky over a white ground against an opening source: total E within %.2e\n",
              worst);
}

// ---- transmittance

TEST(DaylightTransmittance, ScalesTheLightThroughTheOpening) {
  const Scene clear = roomScene("cie-overcast", 1.0);
  const Scene glazed = roomScene("cie-overcast", 0.7);
  const std::vector<SamplePoint> points = windowPoints();
  const std::vector<double> e1 = exactDaylight(clear, points), e7 = exactDaylight(glazed, points);
  const std::vector<double> k1 = kernelDaylight(clear, points), k7 = kernelDaylight(glazed, points);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(e7[i], 0.7 * e1[i], 1e-12 * e1[i]) << points[i].position.transpose();
    EXPECT_NEAR(k7[i], 0.7 * k1[i], 1e-6 * k1[i]) << points[i].position.transpose();
  }
}

// ---- the scene file

TEST(DaylightScene, AnOpeningSourceOfItsOwnWinsOverTheSky) {
  const Scene scene =
      parseScene(roomYaml("sky: {model: uniform, horizontal_illuminance_lx: 10000}\n", 0.5) +
                     "sources:\n  - {name: view, opening: w1, luminance: 1000}\n",
                 "daylight.yaml");
  ASSERT_EQ(scene.sources.size(), 1u);
  EXPECT_DOUBLE_EQ(scene.sources[0].luminance, 500.0);      // τ applies to it too
  EXPECT_EQ(daylightScene(scene, 1.0).sources.size(), 1u);  // no sky through w1
  const Scene sky = roomScene("uniform");
  const Scene lit = daylightScene(sky, 1.0);
  ASSERT_EQ(lit.sources.size(), 2u);
  EXPECT_EQ(lit.sources[0].name, "w1.sky");
  EXPECT_EQ(lit.sources[1].name, "w1.ground");
}

TEST(DaylightScene, BadSkiesAndTransmittancesNameTheirLine) {
  const auto error = [](const std::string& yaml) { return sceneErrorOf(yaml, "d.yaml"); };
  SceneError e = error(roomYaml("sky: {model: clear, horizontal_illuminance_lx: 10000}\n", 1.0));
  EXPECT_EQ(e.line(), 2);
  EXPECT_NE(e.message().find("unknown sky model 'clear'"), std::string::npos) << e.what();
  e = error(roomYaml("sky: {model: uniform, horizontal_illuminance_lx: 10000}\n", 1.5));
  EXPECT_NE(e.message().find("a transmittance must lie in [0, 1], got 1.5"), std::string::npos)
      << e.what();
  e = error(roomYaml("sky: {model: uniform, horizontal_illuminance_lx: 0}\n", 1.0));
  EXPECT_EQ(e.line(), 2);
  e = error("penumbra: 1\nsky: {model: uniform, horizontal_illuminance_lx: 10000}\n");
  EXPECT_NE(e.message().find("no 'room:' with 'openings:'"), std::string::npos) << e.what();
}

// ---- daylight factor figures

TEST(DaylightFactor, FiguresOfAKnownSetOfValues) {
  // E 100, 200, 300, 400 lx under E_h = 10 000 lx: DF 1, 2, 3, 4 %.
  const std::vector<double> total = {300.0, 100.0, 400.0, 200.0};
  const std::vector<double> direct = {250.0, 50.0, 350.0, 150.0};
  const DaylightMetrics m = daylightMetrics(total, direct, 10000.0);
  EXPECT_DOUBLE_EQ(m.mean, 2.5);
  EXPECT_DOUBLE_EQ(m.median, 2.5);
  EXPECT_DOUBLE_EQ(m.min, 1.0);
  EXPECT_DOUBLE_EQ(m.max, 4.0);
  EXPECT_DOUBLE_EQ(m.uniformity, 0.4);
  EXPECT_DOUBLE_EQ(m.directMean, 2.0);
  EXPECT_DOUBLE_EQ(m.internalMean, 0.5);
  const double shares[] = {1.0, 0.75, 0.5, 0.0};  // DF >= 1, 2, 3, 5 %
  ASSERT_EQ(m.shareAtLeast.size(), std::size(shares));
  for (std::size_t k = 0; k < std::size(shares); ++k)
    EXPECT_DOUBLE_EQ(m.shareAtLeast[k], shares[k]) << kDaylightFactorTargets[k];
  EXPECT_DOUBLE_EQ(daylightMetrics({100.0, 500.0, 300.0}, {}, 10000.0).median, 3.0);
}

// ---- EN 17037 daylight provision through the daylight factor

TEST(DaylightProvision, TheUnobstructedSkyMeetsEveryLevel) {
  // DF = 100 % at every point; with E_v,d,med = 15 000 lx the targets are 2 / 0.67 % (minimum),
  // 3.33 / 2 % (medium), 5 / 3.33 % (high).
  const DaylightMetrics m = daylightMetrics(std::vector<double>(12, 10000.0), {}, 10000.0, 15000.0);
  ASSERT_TRUE(m.provision);
  ASSERT_EQ(m.provision->levels.size(), std::size(kDaylightProvisionLevels));
  const double targets[][2] = {{2.0, 100.0 / 150.0}, {10.0 / 3.0, 2.0}, {5.0, 10.0 / 3.0}};
  for (std::size_t k = 0; k < m.provision->levels.size(); ++k) {
    const DaylightProvisionCheck& c = m.provision->levels[k];
    EXPECT_NEAR(c.target, targets[k][0], 1e-12) << kDaylightProvisionLevels[k].name;
    EXPECT_NEAR(c.minimumTarget, targets[k][1], 1e-12) << kDaylightProvisionLevels[k].name;
    EXPECT_EQ(c.shareTarget, 1.0);
    EXPECT_EQ(c.shareMinimumTarget, 1.0);
    EXPECT_TRUE(c.met);
  }
  EXPECT_EQ(m.provision->reached(), "high");
  // Without E_v,d,med there is no verdict.
  EXPECT_FALSE(daylightMetrics({100.0}, {}, 10000.0).provision);
}

// With E_h = E_v,d,med = 10 000 lx, DF = E / 100 and the targets are 3 / 1 % (minimum), 5 / 3 %
// (medium), 7.5 / 5 % (high). 20 points: 1 at DF 0.5 %, 9 at 2 %, 10 at 4 %: DF >= 3 % on
// exactly 50 % and DF >= 1 % on exactly 95 % (the minimum level met at both bounds), DF >= 5 %
// nowhere.
std::vector<double> provisionCase() {
  std::vector<double> e(1, 50.0);
  e.insert(e.end(), 9, 200.0);
  e.insert(e.end(), 10, 400.0);
  return e;
}

TEST(DaylightProvision, SharesAtTheBoundsOfTheMinimumLevel) {
  const DaylightMetrics m = daylightMetrics(provisionCase(), {}, 10000.0, 10000.0);
  ASSERT_TRUE(m.provision);
  const auto& levels = m.provision->levels;
  EXPECT_DOUBLE_EQ(levels[0].target, 3.0);
  EXPECT_DOUBLE_EQ(levels[0].minimumTarget, 1.0);
  EXPECT_DOUBLE_EQ(levels[0].shareTarget, 0.5);
  EXPECT_DOUBLE_EQ(levels[0].shareMinimumTarget, 0.95);
  EXPECT_TRUE(levels[0].met);
  EXPECT_DOUBLE_EQ(levels[1].shareTarget, 0.0);         // DF >= 5 %
  EXPECT_DOUBLE_EQ(levels[1].shareMinimumTarget, 0.5);  // DF >= 3 %
  EXPECT_FALSE(levels[1].met);
  EXPECT_FALSE(levels[2].met);
  EXPECT_EQ(m.provision->reached(), "minimum");

  // One point fewer at DF >= 3 % (45 %): the minimum level fails on its target share.
  std::vector<double> fewer = provisionCase();
  fewer.back() = 290.0;
  const DaylightMetrics f = daylightMetrics(fewer, {}, 10000.0, 10000.0);
  EXPECT_DOUBLE_EQ(f.provision->levels[0].shareTarget, 0.45);
  EXPECT_FALSE(f.provision->levels[0].met);
  EXPECT_EQ(f.provision->reached(), "none");
  // Two points below DF 1 % (90 %): it fails on its minimum target share.
  std::vector<double> dark = provisionCase();
  dark[1] = 99.0;
  const DaylightMetrics d = daylightMetrics(dark, {}, 10000.0, 10000.0);
  EXPECT_DOUBLE_EQ(d.provision->levels[0].shareMinimumTarget, 0.9);
  EXPECT_EQ(d.provision->reached(), "none");
}

TEST(DaylightProvision, TheTablePrintsTargetsSharesAndTheVerdict) {
  RunReport run;
  GridReport grid;
  grid.name = "reference-plane";
  grid.kind = GridKind::WorkPlane;
  grid.daylight = daylightMetrics(provisionCase(), {}, 10000.0, 10000.0);
  run.grids.push_back(grid);
  const std::string table = summaryTable(run);
  EXPECT_NE(table.find("E_v,d,med = 10000 lx"), std::string::npos) << table;
  for (const char* header : {"D_T [%]", "DF >= D_T [% of points]", "D_TM [%]",
                             "DF >= D_TM [% of points]", "E_T [lx]", "E_TM [lx]"})
    EXPECT_NE(table.find(header), std::string::npos) << header << "\n" << table;
  EXPECT_NE(table.find("reference-plane: EN 17037 daylight provision reached: minimum"),
            std::string::npos)
      << table;
  // The minimum level: D_T 3.00 %, 50.00 % of the points; D_TM 1.00 %, 95.00 %; met.
  EXPECT_NE(table.find("3.00 |"), std::string::npos) << table;
  EXPECT_NE(table.find("95.00 |"), std::string::npos) << table;

  run.grids.front().daylight = daylightMetrics(provisionCase(), {}, 10000.0);
  EXPECT_NE(summaryTable(run).find("no verdict without the site's median external diffuse "
                                   "illuminance (site: median_diffuse_illuminance_lx, lx)"),
            std::string::npos);
}

TEST(DaylightProvision, OnlyHorizontalGridsGetAVerdict) {
  // EN 17037's reference plane is horizontal: the work plane (facing +z) is judged, a vertical
  // grid facing the window (−y) is not, whatever its daylight factor.
  const Scene scene = parseScene(
      roomYaml("site: {latitude_deg: 51.5, longitude_deg: -0.1, median_diffuse_illuminance_lx: "
               "10000}\nsky: {model: cie-overcast, horizontal_illuminance_lx: 10000}\n",
               1.0) +
          "grids:\n"
          "  - {name: plane, height: 0.85, spacing: 0.5, margin: 0.5}\n"
          "  - {name: wall, rect: {origin: [1, 2, 0.5], u: [4, 0, 0], v: [0, 0, 1.5]}, "
          "spacing: 0.5}\n",
      "daylight.yaml");
  ASSERT_EQ(scene.grids.size(), 2u);
  // DF 5 % everywhere: every level's targets are met (DF >= D_T = 7.5 % fails the high level).
  const IlluminanceEstimator estimate = [](std::span<const SamplePoint> points) {
    return PointIlluminance(std::vector<double>(points.size(), 500.0));
  };
  RunReport run;
  for (const CalculationGrid& grid : scene.grids)
    run.grids.push_back(
        streamedGridReport(grid, streamGrid(scene, grid, estimate, 64, GridBatchSink{})));
  const GridReport& plane = run.grids[0];
  const GridReport& wall = run.grids[1];
  EXPECT_TRUE(facesUp(scene.grids[0]));
  EXPECT_FALSE(facesUp(scene.grids[1]));
  ASSERT_TRUE(plane.daylight && wall.daylight);
  EXPECT_DOUBLE_EQ(plane.daylight->mean, 5.0);
  EXPECT_DOUBLE_EQ(wall.daylight->mean, 5.0);
  ASSERT_TRUE(plane.daylight->provision);
  EXPECT_EQ(plane.daylight->provision->reached(), "medium");
  EXPECT_FALSE(wall.daylight->provision);
  const std::string table = summaryTable(run);
  EXPECT_NE(table.find("plane: EN 17037 daylight provision reached: medium"), std::string::npos)
      << table;
  EXPECT_NE(table.find("wall: no EN 17037 verdict: the grid does not face up"), std::string::npos)
      << table;
  EXPECT_EQ(table.find("wall: EN 17037 daylight provision reached"), std::string::npos) << table;
}

TEST(DaylightProvision, TheSiteGivesTheMedianDiffuseIlluminance) {
  const Scene scene = parseScene(
      roomYaml("site: {latitude_deg: 51.5, longitude_deg: -0.1, median_diffuse_illuminance_lx: "
               "14000}\nsky: {model: cie-overcast, horizontal_illuminance_lx: 10000}\n",
               1.0),
      "daylight.yaml");
  ASSERT_TRUE(scene.site && scene.site->medianDiffuseIlluminance);
  EXPECT_EQ(*scene.site->medianDiffuseIlluminance, 14000.0);
  const SceneError e = sceneErrorOf(
      roomYaml("site: {latitude_deg: 51.5, longitude_deg: 0, median_diffuse_illuminance_lx: -1}\n",
               1.0),
      "d.yaml");
  EXPECT_EQ(e.line(), 2);
  EXPECT_NE(e.key().find("median_diffuse_illuminance_lx"), std::string::npos) << e.what();
}

TEST(DaylightFactor, CsvRowsCarryDfInPercentAndItsPartsAddUp) {
  EXPECT_EQ(gridCsvHeader(true, true),
            "x_m,y_m,z_m,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,DF_pct,DF_direct_pct,"
            "DF_internal_pct,SC_pct,ERC_pct,IRC_pct,inside\n");
  EXPECT_EQ(gridCsvHeader(false, true), "x_m,y_m,z_m,nx,ny,nz,E_lx,DF_pct,inside\n");
  GridRows rows(NumberDigits::Double);
  rows.setOutdoorIlluminance(10000.0);
  rows.add(Vec3(1, 2, 0.85), Vec3::UnitZ(), 250.0, 200.0, "");
  rows.add(Vec3(1, 2, 0.85), Vec3::UnitZ(), 125.0, "");
  // E 250 lx of 10 000: DF 2.5 %, 2 % direct, 0.5 % internal, and with no split given SC 2 %,
  // ERC 0, IRC 0.5 %; E 125 lx: 1.25 %.
  EXPECT_EQ(rows.csv(), "1,2,0.85,0,0,1,250,200,50,2.5,2,0.5,2,0,0.5,\n1,2,0.85,0,0,1,125,1.25,\n");
}

TEST(DaylightFactor, TheTableHasADfRowPerGrid) {
  RunReport run;
  GridReport grid;
  grid.name = "reference-plane";
  grid.kind = GridKind::WorkPlane;
  grid.daylight = daylightMetrics({100.0, 200.0, 300.0, 400.0}, {}, 10000.0);
  run.grids.push_back(grid);
  const std::string table = summaryTable(run);
  EXPECT_NE(table.find("DF: daylight factor, 100 · E / 10000 lx"), std::string::npos) << table;
  EXPECT_NE(table.find("DF >= 2 % [% of points]"), std::string::npos) << table;
  // DFavg 2.50, median 2.50, min 1.00, uniformity 0.400, shares 100, 75, 50, 0 %.
  EXPECT_NE(table.find("2.50 |         2.50 |      1.00 |       0.400 |"), std::string::npos)
      << table;
  EXPECT_NE(table.find("75.00"), std::string::npos) << table;
}

}  // namespace
}  // namespace penumbra
