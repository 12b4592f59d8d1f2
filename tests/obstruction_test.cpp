// Solids outside the room (an overhang, fins, a building across the street) block the sky, the
// ground and the sun seen through a window (illuminance/skylight.hpp, illuminance/sunlight.hpp;
// docs/method.md "Obstructions outside the room"): against a quadrature of the sky's luminance
// over the visible window written here, each sample's ray tested against the obstructions; a
// point whose whole view of the sky is hidden; the host's path against the kernel's where the
// obstruction hides nothing, with and without interreflection; the sun in an overhang's shadow.
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
#include "illuminance/estimator.hpp"
#include "illuminance/skylight.hpp"
#include "illuminance/sunlight.hpp"
#include "scene/daylight.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"
#include "window_sky_quadrature.hpp"

namespace penumbra {
namespace {

using testing::cpuDevice;
using testing::gaussLegendreOn;
using testing::IntervalRule;

// The window: wall y0 (the room side y = 0, the outside y = −kWall), x 2..4 m, z 0.9..2.4 m.
constexpr double kX0 = 2.0, kX1 = 4.0, kZ0 = 0.9, kZ1 = 2.4, kWall = 0.2;

// An axis-aligned box outside the room (m).
struct Box {
  Vec3 lo, hi;
  std::string yaml(const std::string& name) const {
    const auto v = [](const Vec3& p) {
      return "[" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " +
             std::to_string(p.z()) + "]";
    };
    return "  - {name: " + name + ", box: {min: " + v(lo) + ", max: " + v(hi) + "}}\n";
  }
  // Whether the ray p + t·d, t > 0, meets the box's interior (the slab test).
  bool hitBy(const Vec3& p, const Vec3& d) const {
    double t0 = 0.0, t1 = INFINITY;
    for (int i = 0; i < 3; ++i) {
      if (d[i] == 0.0) {
        if (p[i] <= lo[i] || p[i] >= hi[i]) return false;
        continue;
      }
      double a = (lo[i] - p[i]) / d[i], b = (hi[i] - p[i]) / d[i];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a), t1 = std::min(t1, b);
    }
    return t0 < t1;
  }
};

// An overhang over the window's head, 1 m deep, far wider than the window; fins 0.8 m deep at
// both jambs, up to 10 m, their footings 1 m below the ground (the ground is the directions below
// the horizon, no solid: so their lower ends, whose edges along y would land on the window
// slanted, stay out of every point's view through it); a building across the street, 8 m away,
// 9 m high, wide. Every edge a point sees through the window then runs along x or z.
const Box kOverhang{Vec3(-20.0, -1.2, 2.4), Vec3(26.0, -kWall, 2.5)};
const Box kFinLeft{Vec3(1.8, -1.0, -1.0), Vec3(1.9, -kWall, 10.0)};
const Box kFinRight{Vec3(4.1, -1.0, -1.0), Vec3(4.2, -kWall, 10.0)};
const Box kBuilding{Vec3(-40.0, -18.2, 0.0), Vec3(46.0, -8.2, 9.0)};

std::string obstructedYaml(const std::string& model, double groundReflectance,
                           const std::vector<Box>& boxes) {
  std::string yaml = "penumbra: 1\nsky: {model: " + model +
                     ", horizontal_illuminance_lx: 10000, ground_reflectance: " +
                     std::to_string(groundReflectance) +
                     "}\n"
                     "room:\n"
                     "  size: [6, 4, 3]\n"
                     "  wall_thickness: 0.2\n"
                     "  openings:\n"
                     "    - {name: w1, wall: y0, x: 2.0, z: 0.9, width: 2.0, height: 1.5}\n";
  if (!boxes.empty()) yaml += "solids:\n";
  for (std::size_t k = 0; k < boxes.size(); ++k)
    yaml += boxes[k].yaml("outside-" + std::to_string(k));
  return yaml;
}

// Where the line of the boxes' edges parallel to x (at depth y, height z) lands on the window's
// outer plane seen from p: a height; and the edges parallel to z (at x, y): an abscissa.
double heightOnWindow(const Vec3& p, double y, double z) {
  return p.z() + (z - p.z()) * (-kWall - p.y()) / (y - p.y());
}
double abscissaOnWindow(const Vec3& p, double x, double y) {
  return p.x() + (x - p.x()) * (-kWall - p.y()) / (y - p.y());
}

// E at P (normal n) from the sky and the ground through the window past `boxes`, by definition:
//   E = ∫ L(ω) V(ω) (n·ω)⁺ cos θ_s / d² dA
// over the part of the window's outer rectangle that P sees through its room-side rectangle,
// V(ω) = 0 where the ray from P through the sample meets a box. Every box edge seen through the
// window is parallel to x or z, so its shadow's outline on the window is along the lines where
// those edges land: the rectangle is cut there and at z = P.z, the integrand is smooth on each
// cell, and each cell takes a 48 × 48-point Gauss–Legendre rule.
double quadratureE(const Sky& sky, const SamplePoint& point, const std::vector<Box>& boxes) {
  const Vec3 p = point.position, n = point.normal;
  const double k = (p.y() + kWall) / p.y();  // the room-side rectangle, projected from P
  const double x0 = std::max(kX0, p.x() + (kX0 - p.x()) * k);
  const double x1 = std::min(kX1, p.x() + (kX1 - p.x()) * k);
  const double z0 = std::max(kZ0, p.z() + (kZ0 - p.z()) * k);
  const double z1 = std::min(kZ1, p.z() + (kZ1 - p.z()) * k);
  if (x1 <= x0 || z1 <= z0) return 0.0;
  std::vector<double> xs{x0, x1}, zs{z0, z1, p.z()};
  for (const Box& b : boxes)
    for (double y : {b.lo.y(), b.hi.y()}) {
      if (!(y < -kWall + 1e-12)) continue;  // a face on the wall's plane projects onto itself
      for (double z : {b.lo.z(), b.hi.z()}) zs.push_back(heightOnWindow(p, y, z));
      for (double x : {b.lo.x(), b.hi.x()}) xs.push_back(abscissaOnWindow(p, x, y));
    }
  for (const Box& b : boxes)  // faces on the wall's plane: their own edges
    if (b.hi.y() >= -kWall - 1e-12) {
      zs.insert(zs.end(), {b.lo.z(), b.hi.z()});
      xs.insert(xs.end(), {b.lo.x(), b.hi.x()});
    }
  testing::piecesWithin(xs, x0, x1);
  testing::piecesWithin(zs, z0, z1);
  const double lz = sky.zenithLuminance(), lg = sky.groundLuminance();
  double e = 0.0;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i)
    for (std::size_t j = 0; j + 1 < zs.size(); ++j) {
      const IntervalRule u = gaussLegendreOn(48, xs[i], xs[i + 1]),
                         v = gaussLegendreOn(48, zs[j], zs[j + 1]);
      for (std::size_t a = 0; a < u.x.size(); ++a)
        for (std::size_t b = 0; b < v.x.size(); ++b) {
          const Vec3 d = Vec3(u.x[a], -kWall, v.x[b]) - p;
          if (std::any_of(boxes.begin(), boxes.end(),
                          [&](const Box& box) { return box.hitBy(p, d); }))
            continue;
          const double r = d.norm();
          const Vec3 omega = d / r;
          const double l = omega.z() < 0.0                      ? lg
                           : sky.model == SkyModel::CieOvercast ? lz * (1.0 + 2.0 * omega.z()) / 3.0
                                                                : lz;
          e += u.w[a] * v.w[b] * l * std::max(0.0, n.dot(omega)) * (-omega.y()) / (r * r);
        }
    }
  return e;
}

// Points on the work plane, near the jambs, below the sill facing the window, above the head
// facing it, at mid-height, and on a vertical plane across the window.
std::vector<SamplePoint> roomPoints() {
  const Vec3 up = Vec3::UnitZ(), facing = -Vec3::UnitY(), side = Vec3::UnitX();
  return {
      {Vec3(3.0, 1.0, 0.8), up, -1},     {Vec3(2.05, 0.3, 0.8), up, -1},
      {Vec3(5.5, 2.0, 0.8), up, -1},     {Vec3(3.0, 0.4, 0.5), facing, -1},
      {Vec3(3.0, 0.6, 2.7), facing, -1}, {Vec3(3.0, 1.5, 1.6), facing, -1},
      {Vec3(3.3, 3.5, 1.2), facing, -1}, {Vec3(1.0, 1.0, 1.2), side, -1},
  };
}

// The run's E through the Estimator (kernel for the scene's own sources, the host's sky), direct
// light only.
std::vector<double> directE(const Scene& scene, const std::vector<SamplePoint>& points) {
  EstimatorOptions options;
  options.device = "cpu";
  options.interreflection = false;
  Estimator estimator(options, scene);
  return estimator.illuminance(points).total;
}

TEST(ObstructedSky, OverhangFinsAndABuildingAcrossMatchAQuadratureOfTheVisibleSky) {
  const std::vector<std::vector<Box>> cases = {
      {kOverhang}, {kFinLeft, kFinRight}, {kBuilding}, {kOverhang, kFinLeft, kFinRight, kBuilding}};
  const char* names[] = {"overhang", "fins", "building across", "all of them"};
  for (const std::string model : {"cie-overcast", "uniform"})
    for (std::size_t c = 0; c < cases.size(); ++c) {
      const Scene scene = parseScene(obstructedYaml(model, 0.2, cases[c]), "obstructed.yaml");
      const Scene open = parseScene(obstructedYaml(model, 0.2, {}), "open.yaml");
      ASSERT_TRUE(skyOnHost(scene));
      ASSERT_FALSE(skyOnHost(open));
      const std::vector<SamplePoint> points = roomPoints();
      const std::vector<double> e = directE(scene, points);
      const std::vector<double> unobstructed = directE(open, points);
      double worst = 0.0, hidden = 0.0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const double q = quadratureE(*scene.sky, points[i], cases[c]);
        const double q0 = quadratureE(*scene.sky, points[i], {});
        ASSERT_GT(q0, 0.0) << points[i].position.transpose();
        worst = std::max(worst, std::abs(e[i] - q) / q0);
        hidden = std::max(hidden, 1.0 - q / q0);
        EXPECT_NEAR(e[i], q, 1e-9 * q0)
            << model << ", " << names[c] << " at " << points[i].position.transpose();
        // Without the obstruction, the same quadrature is the kernel's result.
        EXPECT_NEAR(unobstructed[i], q0, 1e-5 * q0) << points[i].position.transpose();
      }
      EXPECT_GT(hidden, 0.1) << names[c];  // the obstruction hides a good part of some view
      std::printf(
          "  %s, %s: largest |E − quadrature| / E_unobstructed %.2e (up to %.0f %% hidden)\n",
          model.c_str(), names[c], worst, 100.0 * hidden);
    }
}

TEST(ObstructedSky, APointWhoseWholeSkyIsHiddenGetsOnlyTheGround) {
  // A building 6 m across and 40 m high: a point below the sill looks up through the window and
  // sees only the building, black to the sky; with a black ground nothing reaches it.
  const Box tower{Vec3(-40.0, -16.2, 0.0), Vec3(46.0, -6.2, 40.0)};
  const SamplePoint low{Vec3(3.0, 2.0, 0.5), -Vec3::UnitY(), -1};
  const SamplePoint mid{Vec3(3.0, 2.0, 1.6), -Vec3::UnitY(), -1};
  const Scene dark = parseScene(obstructedYaml("cie-overcast", 0.0, {tower}), "tower.yaml");
  const Scene open = parseScene(obstructedYaml("cie-overcast", 0.0, {}), "open.yaml");
  EXPECT_GT(directE(open, {low}).front(), 0.0);
  EXPECT_EQ(directE(dark, {low}).front(), 0.0);
  // At mid-height the point also sees the ground below its horizon, up to where the building
  // hides it: with ρ_g = 0.2 that part alone, against the quadrature.
  const Scene grey = parseScene(obstructedYaml("cie-overcast", 0.2, {tower}), "tower.yaml");
  Sky groundOnly = *grey.sky;
  const double e = directE(grey, {mid}).front();
  const double q = quadratureE(groundOnly, mid, {tower});
  EXPECT_GT(q, 0.0);
  EXPECT_NEAR(e, q, 1e-9 * q);
  // Every sky direction the point sees through the window meets the tower: its E is the
  // ground's alone, what the black-ground scene gives it is nothing.
  EXPECT_EQ(directE(dark, {mid}).front(), 0.0);
}

// An obstruction behind the room hides nothing through the window: the host's path (taken
// because a solid stands outside) gives the kernel's result for the scene without it, with
// and without interreflection.
TEST(ObstructedSky, AnObstructionThatHidesNothingGivesTheKernelsResult) {
  const Box behind{Vec3(0.0, 6.0, 0.0), Vec3(6.0, 7.0, 5.0)};
  const std::string materials = "materials: {white: 0.8, grey: 0.4}\n";
  const auto yaml = [&](const std::vector<Box>& boxes) {
    std::string y = obstructedYaml("cie-overcast", 0.2, boxes);
    y.insert(y.find("room:\n") + 6, "  materials: {floor: grey, ceiling: white, walls: white}\n");
    return materials + y;
  };
  const Scene with = parseScene(yaml({behind}), "behind.yaml");
  const Scene without = parseScene(yaml({}), "open.yaml");
  ASSERT_TRUE(skyOnHost(with));
  std::vector<SamplePoint> points = roomPoints();
  for (double z : {0.3, 1.1, 1.65, 2.2, 2.8})
    points.push_back({Vec3(3.0, 3.0, z), -Vec3::UnitY(), -1});
  EstimatorOptions options;
  options.device = "cpu";
  options.mesh.refinementLevels = 0;
  Estimator a(options, with), b(options, without);
  const PointIlluminance ea = a.illuminance(points), eb = b.illuminance(points);
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_GT(eb.total[i], eb.direct[i]) << points[i].position.transpose();
    worst = std::max(worst, std::abs(ea.total[i] - eb.total[i]) / eb.total[i]);
    EXPECT_NEAR(ea.direct[i], eb.direct[i], Tolerance::kKernelRelative * eb.direct[i])
        << points[i].position.transpose();
    EXPECT_NEAR(ea.total[i], eb.total[i], 1e-5 * eb.total[i]) << points[i].position.transpose();
  }
  std::printf("  host sky against kernel sky, with interreflection: total E within %.2e\n", worst);
}

// ---- the sun

void placeSun(Scene& scene, const Vec3& s) {
  Sun sun;
  sun.directNormalIlluminance = 60000.0;
  sun.direction = s;
  sun.position.apparentElevationDegrees = std::asin(s.z()) * 180.0 / std::numbers::pi;
  scene.sun = sun;
}

TEST(ObstructedSun, APointInTheOverhangsShadowGetsNoSun) {
  Scene with = parseScene(obstructedYaml("uniform", 0.2, {kOverhang}), "overhang.yaml");
  Scene without = parseScene(obstructedYaml("uniform", 0.2, {}), "open.yaml");
  const Vec3 s = Vec3(0.0, -0.7, 0.55).normalized();
  placeSun(with, s);
  placeSun(without, s);
  // The ray towards the sun from a floor point crosses the window's outer plane at height z_w;
  // it meets the overhang's underside (z = 2.4, 1 m deep) when (2.4 − z_w)·0.7/0.55 < 1, that is
  // z_w > 1.614 m. The sun's radius, 0.265°, moves that line by under 1 cm at 1.3 m.
  int floor = -1;
  for (int i = 0; i < static_cast<int>(with.solids.size()); ++i)
    if (with.solids[i].name == "room.floor") floor = i;
  const auto floorPointBelow = [&](double zw) {
    const Vec3 w(3.0, -kWall, zw);
    return SamplePoint{w - (zw / s.z()) * s, Vec3::UnitZ(), floor};
  };
  const std::vector<SamplePoint> shaded = {floorPointBelow(2.0), floorPointBelow(1.8)};
  const std::vector<SamplePoint> lit = {floorPointBelow(1.2), floorPointBelow(1.4)};
  for (const SamplePoint& p : shaded) {
    const SamplePoint one[] = {p};
    EXPECT_NEAR(sunlight(without, one).front(), 60000.0 * s.z(), 1e-9 * 60000.0);
    EXPECT_EQ(sunlight(with, one).front(), 0.0) << p.position.transpose();
  }
  for (const SamplePoint& p : lit) {
    const SamplePoint one[] = {p};
    EXPECT_NEAR(sunlight(with, one).front(), 60000.0 * s.z(), 1e-9 * 60000.0)
        << p.position.transpose();
  }
}

}  // namespace
}  // namespace penumbra
