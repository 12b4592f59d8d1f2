// Penumbrae of a small, distant source, held against an exact answer computed another way.
//
// A 0.6 m ceiling panel 10 m from the point, partly hidden by a chair back 0.4 m from it (the open
// office's far panels seen past the near furniture). The occlusion tests' criterion (2e-3 of the
// unoccluded value, tests/occlusion_test.cpp) is set by the reference's sampling and is too loose
// here: a visible contour assembled from crossing points that each edge computes for itself errs by
// up to 2.0e-3 (eight lanes) and 1.3e-3 (scalar) of this panel's light, because a gap of δ rad in a
// contour costs about L·δ however small the source looks; the kernel gives both edges one crossing
// direction (kernels/contour.cl, crossing_direction). The panel is small against its distance, so
// every path takes the terms relative to its reference vertex (kernels/contour.cl, PnPieceForm):
// each path is held to kPenumbraPastNearBox of the panel's unoccluded value, about twice the
// float rounding of the unoccluded formula itself at these points (8.9e-6 measured, 12° above the
// horizon). Measured: 9.3e-6 on every path (4.2e-5 culled, 5.3e-5 plain with each piece's term
// taken alone).
//
// The exact value: reference/exact_illuminance (the box projected from P onto the panel's plane is
// a convex polygon; E is the contour integral in double over the panel minus that polygon).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "engine/illuminance_engine.hpp"
#include "geometry/tolerance.hpp"
#include "reference/exact_illuminance.hpp"
#include "test_device.hpp"
#include "test_scenes.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;
using Vec2 = Eigen::Vector2d;

struct PanelPastBox {
  Vec2 panelMin, panelMax;
  double height, luminance;
  Vec3 boxMin, boxMax;
};

// The kernel's three paths for a scene with solids: each is held to the same bound.
struct EnginePath {
  const char* name;
  EngineOptions options;
};
const EnginePath kEnginePaths[] = {{"culled, eight lanes", {true, true, true}},
                                   {"culled, scalar", {true, true, false}},
                                   {"plain (--no-culling)", {false}}};

constexpr double kPenumbraPastNearBox = 2e-5;

// Each engine path's E at `points` against the exact E, relative to the unoccluded E, within
// `bound`; prints each path's worst.
struct PathCheck {
  const Scene& scene;
  const std::vector<SamplePoint>& points;
  const std::vector<double>& exact;
  const std::vector<double>& unoccluded;
  int penumbra;  // how many points lie in the penumbra, for the printout
};

void expectEveryPathWithin(const PathCheck& check, double bound) {
  for (const EnginePath& path : kEnginePaths) {
    const std::vector<double> e =
        IlluminanceEngine(cpuDevice(), check.scene, path.options).illuminance(check.points);
    double worst = 0.0;
    for (std::size_t k = 0; k < check.points.size(); ++k) {
      const double error = std::abs(e[k] - check.exact[k]) / check.unoccluded[k];
      worst = std::max(worst, error);
      EXPECT_LE(error, bound) << path.name << " at (" << check.points[k].position.transpose()
                              << "): E = " << e[k] << " lx, exact " << check.exact[k] << " lx";
    }
    std::printf("%s: %zu points (%d in the penumbra), max |E - exact| / E_unoccluded = %.2e\n",
                path.name, check.points.size(), check.penumbra, worst);
  }
}

// The open office's panel at (1.5, 1.5) and the chair back of its workstation 20, seen from the
// work plane beside that chair: points from full light through the penumbra into the umbra.
TEST(DistantSource, PenumbraPastANearBoxMeetsTheExactProjection) {
  const PanelPastBox setup{{1.2, 1.2}, {1.8, 1.8},        2.99,
                           3006.26,    {9.97, 5.95, 0.5}, {10.43, 6.0, 0.95}};
  Scene scene;
  scene.sources.push_back(ceilingRect(setup.panelMin.x(), setup.panelMin.y(), setup.panelMax.x(),
                                      setup.panelMax.y(), setup.height, setup.luminance));
  scene.solids.push_back(boxSolid(setup.boxMin, setup.boxMax, "chair-back"));
  std::vector<SamplePoint> points;
  for (int i = 0; i <= 50; ++i)
    for (int j = 0; j <= 20; ++j)
      points.push_back({Vec3(10.4 + 0.01 * i, 6.25 + 0.01 * j, 0.8), Vec3::UnitZ(), -1});
  Scene open = scene;
  open.solids.clear();
  const std::vector<double> exact = exactIlluminance(scene, points)[0];
  const std::vector<double> unoccluded = exactIlluminance(open, points)[0];
  int penumbra = 0;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (exact[k] > 1e-3 * unoccluded[k] && exact[k] < (1 - 1e-3) * unoccluded[k]) ++penumbra;
  ASSERT_GE(penumbra, 200) << "the points should cross the penumbra";

  const std::vector<double> lit = IlluminanceEngine(cpuDevice(), open).illuminance(points);
  double floorError = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k)
    floorError = std::max(floorError, std::abs(lit[k] - unoccluded[k]) / unoccluded[k]);
  std::printf("unoccluded formula: max |E - exact| / E_unoccluded = %.2e\n", floorError);
  expectEveryPathWithin(PathCheck{scene, points, exact, unoccluded, penumbra},
                        kPenumbraPastNearBox);
}

// A 0.1 m Lambertian panel 4 m above a floor and 4 m from a wall, every point seeing it unoccluded:
// each edge's term is of the order of the panel's angular size (1/40 rad) and the terms cancel to
// E, of its square, so the kernel keeps E to a few roundings only because it takes the terms
// relative to a vertex of the face (kernels/arc_term.cl; 1.3e-5 of E with each term taken alone).
// Every path is held to 1e-6 of the exact contour integral in double (16 float roundings of E).
// Measured: 5.7e-7 on every path.
constexpr double kSmallFaceRelative = 1e-6;

TEST(DistantSource, ASmallPanelFarAwayMeetsTheExactContourIntegral) {
  Scene scene;
  scene.sources.push_back(ceilingRect(-0.05, -0.05, 0.05, 0.05, 4.0, 1000.0));
  std::vector<SamplePoint> points;
  for (int i = 0; i <= 24; ++i)
    for (int j = 0; j <= 24; ++j) {
      const double u = -4.0 + i / 3.0, v = -4.0 + j / 3.0;
      points.push_back({Vec3(u, v, 0.0), Vec3::UnitZ(), -1});                // the floor
      points.push_back({Vec3(4.0, v, 0.1 + 0.15 * i), -Vec3::UnitX(), -1});  // a wall at 4 m
    }
  const std::vector<double> exact = exactIlluminance(scene, points)[0];
  for (const EnginePath& path : kEnginePaths) {
    const std::vector<double> e =
        IlluminanceEngine(cpuDevice(), scene, path.options).illuminance(points);
    double worst = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      ASSERT_GT(exact[k], 0.0) << points[k].position.transpose();
      const double error = std::abs(e[k] - exact[k]) / exact[k];
      worst = std::max(worst, error);
      EXPECT_LE(error, kSmallFaceRelative)
          << path.name << " at (" << points[k].position.transpose() << "): E = " << e[k]
          << " lx, exact " << exact[k] << " lx";
    }
    std::printf("%s: %zu points, max |E - exact| / E = %.2e\n", path.name, points.size(), worst);
  }
}

// The same 0.1 m panel past a table 0.75 m high, seen from the floor across two of the table's
// shadow edges up to 3.7 m from the panel's nadir, where the penumbra is 23 to 30 mm wide: the
// penumbra paths take the visible contour's terms relative to the panel's reference vertex as the
// unoccluded path does (kernels/contour.cl, PnPieceForm). Every path is held to kSmallFacePastTable
// of the point's unoccluded E against the exact reference in double (the panel minus the table's
// shadow projected on its plane). What is left is the rounding of the directions the contour's
// ends come from (the table's vertices from the point, the side planes and their crossings),
// about 2⁻²⁴ rad each, which moves the visible region's edge by that over the panel's angular
// size (1/50 rad, foreshortened, at the farthest points). Measured: 5.2e-6 on every path, against
// 1.15e-5 with each piece's term taken alone.
constexpr double kSmallFacePastTable = 8e-6;

TEST(DistantSource, ASmallPanelPastATableMeetsTheExactReferenceOnEveryPath) {
  Scene scene;
  scene.sources.push_back(ceilingRect(-0.05, -0.05, 0.05, 0.05, 4.0, 1000.0));
  scene.solids.push_back(boxSolid(Vec3(-0.5, -0.45, 0.72), Vec3(3.0, 0.3, 0.75), "table"));
  Scene open = scene;
  open.solids.clear();
  std::vector<SamplePoint> points;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; j <= 12; ++j) {
      points.push_back({Vec3(3.66 + 0.001 * i, -0.5 + 0.07 * j, 0.0), Vec3::UnitZ(), -1});  // x
      points.push_back({Vec3(0.5 + 0.24 * j, 0.34 + 0.001 * i, 0.0), Vec3::UnitZ(), -1});   // y
    }
  const std::vector<double> exact = exactIlluminance(scene, points)[0];
  const std::vector<double> unoccluded = exactIlluminance(open, points)[0];
  int penumbra = 0;
  for (std::size_t k = 0; k < points.size(); ++k)
    if (exact[k] > 1e-3 * unoccluded[k] && exact[k] < (1 - 1e-3) * unoccluded[k]) ++penumbra;
  ASSERT_GE(penumbra, 300) << "the points should cross the penumbra";
  expectEveryPathWithin(PathCheck{scene, points, exact, unoccluded, penumbra}, kSmallFacePastTable);
}

// Square Lambertian panels of 0.025 to 1.6 m, 4 m above the floor, seen from the floor, a wall and
// planes up to 0.56 m below them, at points that see the panel 30° or more above both horizons:
// the kernel takes the terms relative to a vertex where the panel's largest vertex offset is
// below PN_SMALL_FACE (0.1) of its distance in some lane (kernels/lambert.cl), each term alone
// elsewhere. Both sides of that switch are held to half the kernel's tolerance of the exact
// contour integral in double; each term taken alone errs by up to 9.6e-5 of E on the smallest
// panel. Measured: 3.1e-6 at most (the 0.4 m panel, 2 to 4 m away, each term alone), 1.2e-6 at
// most with the terms taken relative to a vertex.
TEST(DistantSource, PanelsOfEverySizeMeetTheExactIntegralOnBothSidesOfTheSwitch) {
  constexpr double kClearCosine = 0.5;  // 30° above the point's horizon and the panel's
  for (const double size : {0.025, 0.05, 0.1, 0.2, 0.4, 0.8, 1.6}) {
    Scene scene;
    scene.sources.push_back(ceilingRect(-size / 2, -size / 2, size / 2, size / 2, 4.0, 1000.0));
    std::vector<SamplePoint> points;
    for (int i = 0; i <= 24; ++i)
      for (int j = 0; j <= 24; ++j) {
        const double u = -4.0 + i / 3.0, v = -4.0 + j / 3.0;
        for (const SamplePoint& p : {SamplePoint{Vec3(u, v, 0.0), Vec3::UnitZ(), -1},
                                     SamplePoint{Vec3(4.0, v, 0.1 + 0.15 * i), -Vec3::UnitX(), -1},
                                     SamplePoint{Vec3(u, v, 2.0 + 0.06 * j), Vec3::UnitZ(), -1}}) {
          const Vec3 toPanel = (Vec3(0.0, 0.0, 4.0) - p.position).normalized();
          if (p.normal.dot(toPanel) >= kClearCosine && toPanel.z() >= kClearCosine)
            points.push_back(p);
        }
      }
    const std::vector<double> exact = exactIlluminance(scene, points)[0];
    const std::vector<double> e = IlluminanceEngine(cpuDevice(), scene, {}).illuminance(points);
    double worst = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      ASSERT_GT(exact[k], 0.0) << points[k].position.transpose();
      const double error = std::abs(e[k] - exact[k]) / exact[k];
      worst = std::max(worst, error);
      EXPECT_LE(error, 0.5 * Tolerance::kKernelRelative)
          << size << " m panel at (" << points[k].position.transpose() << "): E = " << e[k]
          << " lx, exact " << exact[k] << " lx";
    }
    std::printf("%.3f m panel: %zu points, max |E - exact| / E = %.2e\n", size, points.size(),
                worst);
  }
}

// Square Lambertian panels of 0.1 to 1.2 m at points e above both horizons (the point's and the
// panel's plane), e from 2° to 45°, ρ (diagonal over distance) from 0.005 to 3: the terms keep
// their size while E falls as sin²e, so what float rounding leaves grows relative to E as
// 1/sin²e, on both sides of the PN_SMALL_FACE switch (2.5e-4 of E at 2°, 2.6e-5 at 11.5°, 1.9e-6
// at 45°, docs/method.md). It stays a few roundings of the light the panel gives at that distance
// face-on, E / sin²e: held to kGrazingFaceOn of it.
constexpr double kGrazingFaceOn = 2e-6;

TEST(DistantSource, GrazingViewsErrByAFewRoundingsOfTheFaceOnLight) {
  double worstFaceOn = 0.0, worstOwn = 0.0;
  for (const double size : {0.1, 0.2, 0.4, 0.6, 1.2}) {
    Scene scene;
    scene.sources.push_back(ceilingRect(-size / 2, -size / 2, size / 2, size / 2, 4.0, 1000.0));
    const Vec3 centre(0.0, 0.0, 4.0);
    std::vector<SamplePoint> points;
    std::vector<double> elevations;  // rad
    for (double d = 0.5; d <= 30.0; d *= 1.08)
      for (const double degrees : {2.0, 4.0, 6.0, 8.0, 11.5, 15.0, 20.0, 30.0, 45.0}) {
        const double e = degrees * std::numbers::pi / 180.0;
        // Seen from the panel's centre e below its plane; the point's normal turned so that the
        // centre lies e above its horizon too.
        const Vec3 p = centre + d * Vec3(std::cos(e), 0.3 * std::cos(e), -std::sin(e)).normalized();
        const Vec3 toPanel = (centre - p).normalized();
        const Vec3 up = toPanel.cross(Vec3::UnitZ()).normalized().cross(toPanel);
        points.push_back({p, (std::sin(e) * toPanel + std::cos(e) * up).normalized(), -1});
        elevations.push_back(e);
      }
    const std::vector<double> exact = exactIlluminance(scene, points)[0];
    const std::vector<double> e = IlluminanceEngine(cpuDevice(), scene, {}).illuminance(points);
    for (std::size_t k = 0; k < points.size(); ++k) {
      ASSERT_GT(exact[k], 0.0) << points[k].position.transpose();
      const double faceOn = exact[k] / std::pow(std::sin(elevations[k]), 2);
      const double error = std::abs(e[k] - exact[k]);
      worstFaceOn = std::max(worstFaceOn, error / faceOn);
      worstOwn = std::max(worstOwn, error / exact[k]);
      EXPECT_LE(error, kGrazingFaceOn * faceOn)
          << size << " m panel at (" << points[k].position.transpose() << "), "
          << elevations[k] * 180.0 / std::numbers::pi << "° above both horizons: E = " << e[k]
          << " lx, exact " << exact[k] << " lx";
    }
  }
  std::printf("max |E - exact| / (E / sin²e) = %.2e, / E = %.2e\n", worstFaceOn, worstOwn);
}

}  // namespace
}  // namespace penumbra
