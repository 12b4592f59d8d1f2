// What a daylight run records and how its daylight factor splits (docs/method.md, "Daylight
// factor components"): summary.json's sky read back against the scene's keys and the patch count
// 144 m² + 1; the BRE split DF = SC + ERC + IRC in each CSV row, SC against the run without a
// ground, the ground's part of ERC linear in ρ_g; the light an obstruction's face reflects into
// the room (ERC) against a quadrature written here, nothing from a black one, linear in its ρ.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "illuminance/estimator.hpp"
#include "penumbra_process.hpp"
#include "sanitized_build.hpp"
#include "scene/daylight.hpp"
#include "scene/scene_loader.hpp"
#include "test_files.hpp"
#include "window_sky_quadrature.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using testing::gaussLegendreOn;
using testing::IntervalRule;
using testing::kSanitizedBuild;
using testing::lines;
using testing::readText;
using testing::runPenumbra;
using testing::TempDir;

constexpr double kPi = std::numbers::pi;

// A 6 × 4 × 3 m room, walls 0.2 m, one window in wall y0 (x 2..4 m, z 0.9..2.4 m), under `sky`.
std::string windowRoomYaml(const std::string& sky, const std::string& extra = "") {
  return "penumbra: 1\n" + sky + extra +
         "room:\n"
         "  size: [6, 4, 3]\n"
         "  wall_thickness: 0.2\n"
         "  openings:\n"
         "    - {name: w1, wall: y0, x: 2.0, z: 0.9, width: 2.0, height: 1.5}\n"
         "grids:\n"
         "  - {name: plane, rect: {origin: [1, 0.5, 0.8], u: [4, 0, 0], v: [0, 3, 0]}, "
         "spacing: 1}\n";
}

// The fields of a CSV line.
std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> f(1);
  for (char c : line) {
    if (c == ',')
      f.emplace_back();
    else
      f.back() += c;
  }
  return f;
}

// A column of a grid's CSV by its header's name.
std::vector<double> csvColumn(const fs::path& csv, const std::string& name) {
  const std::vector<std::string> all = lines(readText(csv));
  EXPECT_FALSE(all.empty()) << csv;
  if (all.empty()) return {};
  const std::vector<std::string> header = csvFields(all[0]);
  const auto at = std::find(header.begin(), header.end(), name);
  EXPECT_NE(at, header.end()) << name << " not in " << all[0];
  if (at == header.end()) return {};
  const auto k = static_cast<std::size_t>(at - header.begin());
  std::vector<double> values;
  for (std::size_t i = 1; i < all.size(); ++i) values.push_back(std::stod(csvFields(all[i])[k]));
  return values;
}

// ---- summary.json's sky

TEST(SkySummary, AGridRunRecordsTheSkyAndTheSunAsTheSceneGivesThem) {
  const TempDir dir("sky-summary");
  const std::string general = windowRoomYaml(
      "site: {latitude_deg: 51.5, longitude_deg: -0.1, timezone_h: 0, north_deg: 0}\n"
      "sky: {model: cie-general, type: 12, subdivision: 2, horizontal_illuminance_lx: 12500, "
      "ground_reflectance: 0.15}\n"
      "sun: {date: 2026-03-21, time: \"10:00\", direct_normal_illuminance_lx: 60000}\n");
  std::ofstream(dir.path() / "general.yaml") << general;
  std::ofstream(dir.path() / "overcast.yaml")
      << windowRoomYaml("sky: {model: cie-overcast, horizontal_illuminance_lx: 10000}\n");
  ASSERT_EQ(
      runPenumbra(dir.path(), "grid general.yaml -o general --device cpu -q --direct-only").status,
      0);
  ASSERT_EQ(runPenumbra(dir.path(), "grid overcast.yaml -o overcast --device cpu -q --direct-only")
                .status,
            0);
  const Scene scene = parseScene(general, "general.yaml");
  ASSERT_TRUE(scene.sun);
  const nlohmann::json summary =
      nlohmann::json::parse(readText(dir.path() / "general/summary.json"));
  const nlohmann::json& sky = summary.at("sky");
  EXPECT_EQ(sky.at("model"), "cie-general");
  EXPECT_EQ(sky.at("cie_type"), 12);
  EXPECT_EQ(sky.at("subdivision"), 2);
  EXPECT_EQ(sky.at("patches"), 144 * 2 * 2 + 1);  // Reinhart's 144 m² + 1
  EXPECT_EQ(sky.at("horizontal_illuminance_lx").get<double>(), 12500.0);
  EXPECT_EQ(sky.at("ground_reflectance").get<double>(), 0.15);
  const nlohmann::json& sun = summary.at("sun");
  EXPECT_EQ(sun.at("azimuth_deg").get<double>(), scene.sun->position.azimuthDegrees);
  EXPECT_EQ(sun.at("elevation_deg").get<double>(), scene.sun->position.apparentElevationDegrees);
  EXPECT_EQ(sun.at("direct_normal_illuminance_lx").get<double>(), 60000.0);

  const nlohmann::json overcast =
      nlohmann::json::parse(readText(dir.path() / "overcast/summary.json")).at("sky");
  EXPECT_EQ(overcast.at("model"), "cie-overcast");
  EXPECT_EQ(overcast.at("ground_reflectance").get<double>(), 0.2);  // the default ρ_g
  EXPECT_TRUE(overcast.at("cie_type").is_null());
  EXPECT_TRUE(overcast.at("patches").is_null());
  EXPECT_FALSE(
      nlohmann::json::parse(readText(dir.path() / "overcast/summary.json")).contains("sun"));
}

TEST(SkySummary, TregenzasSubdivisionHas145Patches) {
  const TempDir dir("sky-tregenza");
  std::ofstream(dir.path() / "scene.yaml")
      << windowRoomYaml("sky: {model: cie-general, type: 1, horizontal_illuminance_lx: 10000}\n");
  ASSERT_EQ(runPenumbra(dir.path(), "grid scene.yaml -o out --device cpu -q --direct-only").status,
            0);
  const nlohmann::json sky =
      nlohmann::json::parse(readText(dir.path() / "out/summary.json")).at("sky");
  EXPECT_EQ(sky.at("subdivision"), 1);
  EXPECT_EQ(sky.at("patches"), 145);
}

// ---- DF = SC + ERC + IRC

// A white room under the overcast sky (ρ_g = 0.2), run with interreflection, its grid facing the
// window from 1.5 m at heights across the window and above its head: the three components add up
// to DF in every row; SC is the sky seen through the window and ERC (no obstruction) the ground
// seen through it, each against the quadrature of tests/window_sky_quadrature.hpp (the sky at
// ρ_g = 0, and the difference ρ_g = 0.2 less ρ_g = 0); the means in summary.json are the
// columns'.
TEST(DaylightComponents, AddUpToDfAndSplitTheDirectLightIntoSkyAndGround) {
  const TempDir dir("df-components");
  std::string yaml = windowRoomYaml(
      "sky: {model: cie-overcast, horizontal_illuminance_lx: 10000, ground_reflectance: 0.2}\n",
      "materials: {paint: 0.6}\n");
  yaml.insert(yaml.find("  openings:"),
              "  materials: {floor: paint, ceiling: paint, walls: paint}\n");
  yaml.replace(yaml.find("  - {name: plane"), std::string::npos,
               "  - {name: facing, rect: {origin: [1.5, 1.5, 1.0], u: [3, 0, 0], v: [0, 0, 1.8]}, "
               "spacing: 0.6}\n");
  std::ofstream(dir.path() / "scene.yaml") << yaml;
  // The split does not depend on the mesh: coarser under the sanitizers.
  const std::string run = std::string("grid scene.yaml -o out --device cpu -q --element-size ") +
                          (kSanitizedBuild ? "2" : "1");
  ASSERT_EQ(runPenumbra(dir.path(), run).status, 0);
  const fs::path csv = dir.path() / "out/facing.csv";
  const std::vector<double> df = csvColumn(csv, "DF_pct"), sc = csvColumn(csv, "SC_pct"),
                            erc = csvColumn(csv, "ERC_pct"), irc = csvColumn(csv, "IRC_pct");
  const std::vector<double> x = csvColumn(csv, "x_m"), y = csvColumn(csv, "y_m"),
                            z = csvColumn(csv, "z_m");
  ASSERT_EQ(df.size(), 15u);
  const Scene scene = parseScene(yaml, "scene.yaml");
  Sky skyAlone = *scene.sky;
  skyAlone.groundReflectance = 0.0;
  const testing::WallWindow window{2.0, 4.0, 0.9, 2.4, 0.2, 1.0};
  double worstSky = 0.0, worstGround = 0.0, worstSum = 0.0;
  for (std::size_t i = 0; i < df.size(); ++i) {
    const Vec3 p(x[i], y[i], z[i]), n = -Vec3::UnitY();
    const double sky = testing::windowSkyQuadrature(skyAlone, window, p, n) / 100.0;
    const double ground = testing::windowSkyQuadrature(*scene.sky, window, p, n) / 100.0 - sky;
    ASSERT_GT(ground, 0.0);  // every point sees some ground through the window
    EXPECT_GT(irc[i], 0.0);
    EXPECT_NEAR(sc[i] + erc[i] + irc[i], df[i], 1e-12 * df[i]) << i;
    // The kernel's float sums: SC is the run's direct light less its ground sources'.
    EXPECT_NEAR(sc[i], sky, 1e-5 * (sky + ground)) << p.transpose();
    EXPECT_NEAR(erc[i], ground, 1e-5 * (sky + ground)) << p.transpose();
    worstSky = std::max(worstSky, std::abs(sc[i] - sky) / (sky + ground));
    worstGround = std::max(worstGround, std::abs(erc[i] - ground) / (sky + ground));
    worstSum = std::max(worstSum, std::abs(sc[i] + erc[i] + irc[i] - df[i]) / df[i]);
  }
  std::printf(
      "  SC within %.2e, ERC within %.2e of the quadrature; SC + ERC + IRC = DF within %.1e\n",
      worstSky, worstGround, worstSum);
  const nlohmann::json d = nlohmann::json::parse(
      readText(dir.path() / "out/summary.json"))["grids"][0]["daylight_factor"];
  double scMean = 0.0, ercMean = 0.0;
  for (std::size_t i = 0; i < df.size(); ++i)
    scMean += sc[i] / double(df.size()), ercMean += erc[i] / double(df.size());
  const double mean = d.at("DFavg_pct").get<double>();
  EXPECT_NEAR(d.at("SCavg_pct").get<double>(), scMean, 1e-9 * mean);
  EXPECT_NEAR(d.at("ERCavg_pct").get<double>(), ercMean, 1e-9 * mean);
  EXPECT_NEAR(d.at("SCavg_pct").get<double>() + d.at("ERCavg_pct").get<double>() +
                  d.at("IRCavg_pct").get<double>(),
              mean, 1e-12 * mean);
}

// ---- the externally reflected component from an obstruction's face

constexpr double kWall = 0.2;
// The room's outer box: its interior 6 × 4 × 3 m grown by the walls.
constexpr double kOuterX0 = -kWall, kOuterX1 = 6.0 + kWall, kOuterZ1 = 3.0 + kWall;
// A building across the street: its face towards the window at y = kFaceY, x and z in the
// ranges below, 6 m from the wall's outer plane.
constexpr double kFaceY = -6.2, kFaceX0 = -3.0, kFaceX1 = 9.0, kFaceZ1 = 6.0;
constexpr double kTransmittance = 0.7;

std::string obstructedRoomYaml(const std::string& buildingMaterial, const std::string& walls) {
  std::string yaml =
      "penumbra: 1\n"
      "sky: {model: uniform, horizontal_illuminance_lx: 10000, ground_reflectance: 0}\n"
      "materials: {black: 0, grey: 0.3, white: 0.6, facade: 0.1}\n"
      "room:\n"
      "  size: [6, 4, 3]\n"
      "  wall_thickness: 0.2\n"
      "  materials: {floor: " +
      walls + ", ceiling: " + walls + ", walls: " + walls +
      "}\n"
      "  openings:\n"
      "    - {name: w1, wall: y0, x: 2.0, z: 0.9, width: 2.0, height: 1.5, transmittance: 0.7}\n"
      "solids:\n"
      "  - {name: building, box: {min: [-3, -12, 0], max: [9, -6.2, 6]}";
  if (!buildingMaterial.empty()) yaml += ", material: " + buildingMaterial;
  return yaml + "}\n";
}

// Lambert's projected solid angle (sr) on the unit normal n at p of the polygon `v`.
double projectedSolidAngle(const Vec3& p, const Vec3& n, const std::vector<Vec3>& v) {
  double sum = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3 a = (v[i] - p).normalized(), b = (v[(i + 1) % v.size()] - p).normalized();
    const Vec3 c = a.cross(b);
    if (c.norm() == 0.0) continue;
    sum += std::atan2(c.norm(), a.dot(b)) * n.dot(c.normalized());
  }
  return 0.5 * std::abs(sum);
}

// E (lx) on the building's face at x (normal +y) under the uniform sky of luminance l, ground
// black: the upper quarter of the sphere in front of it, π/2, less the part of the room's outer
// box above x's horizon (its face y = −0.2 and, beside it, its side faces), each a rectangle.
double buildingFaceIlluminance(const Vec3& x, double l) {
  const Vec3 n = Vec3::UnitY();
  const double z0 = std::max(x.z(), -kWall);
  double hidden = 0.0;
  if (z0 < kOuterZ1) {
    hidden +=
        projectedSolidAngle(x, n,
                            {Vec3(kOuterX0, -kWall, z0), Vec3(kOuterX1, -kWall, z0),
                             Vec3(kOuterX1, -kWall, kOuterZ1), Vec3(kOuterX0, -kWall, kOuterZ1)});
    for (const double side : {kOuterX0, kOuterX1}) {
      if ((side == kOuterX0) != (x.x() < kOuterX0) || (side == kOuterX1) != (x.x() > kOuterX1))
        continue;  // a side face x sees: it stands beyond that side
      hidden +=
          projectedSolidAngle(x, n,
                              {Vec3(side, -kWall, z0), Vec3(side, 4.0 + kWall, z0),
                               Vec3(side, 4.0 + kWall, kOuterZ1), Vec3(side, -kWall, kOuterZ1)});
    }
  }
  return l * (kPi / 2.0 - hidden);
}

// The light the building's face (reflectance ρ, Lambertian: L = ρ E/π) sends to p (normal np)
// through the window, times its transmittance: over the part of the face p sees through both of
// the window's rectangles (y = 0 and y = −0.2; the projections of their edges, lines along x and
// z), cut where E has a kink (z = the box's top, x = its sides), each cell a 32 × 32
// Gauss–Legendre rule.
double reflectedQuadrature(const Vec3& p, const Vec3& np, double reflectance) {
  const double l = 10000.0 / kPi;
  const auto onFace = [&](double u, double y) {
    return p[0] + (u - p[0]) * (kFaceY - p.y()) / (y - p.y());
  };
  const auto onFaceZ = [&](double u, double y) {
    return p.z() + (u - p.z()) * (kFaceY - p.y()) / (y - p.y());
  };
  double x0 = kFaceX0, x1 = kFaceX1, z0 = 0.0, z1 = kFaceZ1;
  for (const double y : {0.0, -kWall}) {  // the window's x 2..4, z 0.9..2.4 in both planes
    const double a = onFace(2.0, y), b = onFace(4.0, y);
    x0 = std::max(x0, std::min(a, b)), x1 = std::min(x1, std::max(a, b));
    const double c = onFaceZ(0.9, y), d = onFaceZ(2.4, y);
    z0 = std::max(z0, std::min(c, d)), z1 = std::min(z1, std::max(c, d));
  }
  if (x1 <= x0 || z1 <= z0) return 0.0;
  std::vector<double> xs{x0, x1, kOuterX0, kOuterX1}, zs{z0, z1, kOuterZ1};
  testing::piecesWithin(xs, x0, x1);
  testing::piecesWithin(zs, z0, z1);
  double e = 0.0;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i)
    for (std::size_t j = 0; j + 1 < zs.size(); ++j) {
      const IntervalRule u = gaussLegendreOn(32, xs[i], xs[i + 1]),
                         v = gaussLegendreOn(32, zs[j], zs[j + 1]);
      for (std::size_t a = 0; a < u.x.size(); ++a)
        for (std::size_t b = 0; b < v.x.size(); ++b) {
          const Vec3 x(u.x[a], kFaceY, v.x[b]);
          const Vec3 d = x - p;
          const double r2 = d.squaredNorm(), r = std::sqrt(r2);
          const double luminance = reflectance * buildingFaceIlluminance(x, l) / kPi;
          e += u.w[a] * v.w[b] * luminance * std::max(0.0, np.dot(d) / r) * (-d.y() / r) / r2;
        }
    }
  return kTransmittance * e;
}

std::vector<SamplePoint> facingPoints() {
  const Vec3 up = Vec3::UnitZ(), facing = -Vec3::UnitY();
  return {{Vec3(3.0, 1.0, 0.8), up, -1},
          {Vec3(2.5, 2.0, 0.8), up, -1},
          {Vec3(3.0, 0.5, 1.6), facing, -1},
          {Vec3(4.5, 2.5, 1.2), facing, -1}};
}

PointIlluminance runEstimator(const Scene& scene, std::span<const SamplePoint> points,
                              double elementSize) {
  EstimatorOptions options;
  options.device = "cpu";
  options.mesh.elementSize = elementSize;
  options.mesh.refinementLevels = 0;
  Estimator estimator(options, scene);
  return estimator.illuminance(points);
}

// A black room (its faces reflect nothing): what an interior point gets from the building's face
// is that face's light alone, L = ρ·E_face/π through the glazing. Against the quadrature, at two
// element sizes: the mesh's error (each element at its average E) falls as the elements shrink.
TEST(ExternallyReflected, ABuildingAcrossTheStreetMatchesAQuadratureOfItsLightThroughTheWindow) {
  const Scene scene = parseScene(obstructedRoomYaml("grey", "black"), "building.yaml");
  ASSERT_TRUE(skyOnHost(scene));
  EXPECT_EQ(crossingTransmittance(scene), kTransmittance);
  const std::vector<SamplePoint> points = facingPoints();
  std::vector<double> worst;
  for (const double size :
       kSanitizedBuild ? std::vector<double>{1.0} : std::vector<double>{1.0, 0.5}) {
    const PointIlluminance e = runEstimator(scene, points, size);
    ASSERT_EQ(e.externalComponent.size(), points.size());
    double w = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double expected = reflectedQuadrature(points[i].position, points[i].normal, 0.3);
      ASSERT_GT(expected, 0.0);
      // Ground black: ERC is the building's light alone; the room black: no IRC.
      w = std::max(w, std::abs(e.externalComponent[i] - expected) / expected);
      EXPECT_NEAR(e.total[i] - e.direct[i], e.externalComponent[i], 1e-12 * expected);
      EXPECT_NEAR(e.skyComponent[i], e.direct[i], 1e-12 * e.direct[i]);
    }
    std::printf("  element size %.2f m: ERC within %.2e of the quadrature\n", size, w);
    worst.push_back(w);
  }
  EXPECT_LT(worst.front(), 2e-3);
  if (worst.size() > 1) {
    EXPECT_LT(worst.back(), worst.front());
  }
}

// With the room's faces reflecting: a black building (ρ = 0) gives the result of the same
// building without a material (not meshed) bit for bit, and the light it reflects grows with its
// reflectance, linearly to first order (doubling ρ doubles it within the second bounce's share).
TEST(ExternallyReflected, ABlackBuildingReflectsNothingAndTheComponentGrowsWithItsReflectance) {
  const std::vector<SamplePoint> points = facingPoints();
  const double size = kSanitizedBuild ? 2.0 : 1.0;  // m: the elements
  const PointIlluminance bare =
      runEstimator(parseScene(obstructedRoomYaml("", "white"), "a.yaml"), points, size);
  const PointIlluminance black =
      runEstimator(parseScene(obstructedRoomYaml("black", "white"), "b.yaml"), points, size);
  const PointIlluminance facade =
      runEstimator(parseScene(obstructedRoomYaml("facade", "white"), "c.yaml"), points, size);
  const PointIlluminance grey =
      runEstimator(parseScene(obstructedRoomYaml("grey", "white"), "d.yaml"), points, size);
  double worstRatio = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(black.total[i], bare.total[i]) << i;
    EXPECT_EQ(black.externalComponent[i], 0.0) << i;  // ground black, building black
    ASSERT_GT(facade.externalComponent[i], 0.0);
    // ρ 0.3 against 0.1: three times the light, and more by the share of the building's light
    // that comes back to it off the room and its facade (a second bounce, under 1 %).
    const double ratio = grey.externalComponent[i] / facade.externalComponent[i];
    worstRatio = std::max(worstRatio, ratio);
    EXPECT_GE(ratio, 3.0) << i;
    EXPECT_LT(ratio, 3.0 * 1.01) << i;
    // The building's light also reaches the point after the room's faces: IRC grows too.
    EXPECT_GT(grey.total[i] - grey.direct[i] - grey.externalComponent[i],
              bare.total[i] - bare.direct[i]);
  }
  std::printf("  ERC at rho 0.3 over ERC at rho 0.1: at most %.5f\n", worstRatio);
}

}  // namespace
}  // namespace penumbra
