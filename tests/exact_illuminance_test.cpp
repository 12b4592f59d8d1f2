// The exact reference (host/reference/exact_illuminance) against closed forms, to double
// rounding, and against the sampled reference on scenes with penumbrae, flush and touching
// geometry, to that reference's sampling error. Both references share no code with each other or
// with the kernel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "grid/grid_evaluation.hpp"
#include "reference/exact_illuminance.hpp"
#include "reference/reference_illuminance.hpp"
#include "scene/scene_loader.hpp"
#include "test_scenes.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;

constexpr double kLuminance = 1000.0;  // cd/m²
// Closed forms and the exact reference are both double: they agree to rounding, far below any
// float quantity the kernel is held to.
constexpr double kDoubleRounding = 1e-12;

double exactAt(const Scene& scene, const SamplePoint& point) {
  return exactIlluminance(scene, std::span(&point, 1))[0][0];
}

double exactAtOrigin(const Scene& scene) {
  return exactAt(scene, {Vec3::Zero(), Vec3::UnitZ(), -1});
}

double cornerSquare() {
  return std::numbers::pi * kLuminance * parallelCornerFactor(1, 1, 1);
}

TEST(ExactIlluminance, ParallelSquareWithCornerOverThePoint) {
  Scene scene;
  scene.sources.push_back(ceilingRect(0.0, 0.0, 1.0, 1.0, 1.0, kLuminance));
  EXPECT_NEAR(exactAtOrigin(scene), cornerSquare(), kDoubleRounding * cornerSquare());
}

TEST(ExactIlluminance, PerpendicularRectangle) {
  Scene scene;
  scene.sources.push_back(
      areaSource({{0.0, 1.0, 0.0}, {2.0, 1.0, 0.0}, {2.0, 1.0, 1.5}, {0.0, 1.0, 1.5}}, kLuminance));
  const double exact = std::numbers::pi * kLuminance * perpendicularFactor(2.0, 1.0, 1.5);
  EXPECT_NEAR(exactAtOrigin(scene), exact, kDoubleRounding * exact);
}

TEST(ExactIlluminance, HorizonCutsASourceThroughThePointsPlane) {
  // The perpendicular rectangle extended below the point's plane: only the part above counts.
  Scene scene;
  scene.sources.push_back(areaSource(
      {{0.0, 1.0, -0.7}, {2.0, 1.0, -0.7}, {2.0, 1.0, 1.5}, {0.0, 1.0, 1.5}}, kLuminance));
  const double exact = std::numbers::pi * kLuminance * perpendicularFactor(2.0, 1.0, 1.5);
  EXPECT_NEAR(exactAtOrigin(scene), exact, kDoubleRounding * exact);
}

// Shadows with closed forms: a slab over x >= 0.6·a between heights 0.4 and 0.6 leaves the
// a × 1 rectangle with its corner over the point; four boxes, one per quadrant of a square
// centred over the point, each hiding its quadrant's outer part, leave the centred a × a square.
TEST(ExactIlluminance, ShadowsLeaveRectanglesWithCornerOrCentreOverThePoint) {
  const double a = 0.4713;
  Scene scene;
  scene.sources.push_back(ceilingRect(0.0, 0.0, 1.0, 1.0, 1.0, kLuminance));
  scene.solids.push_back(boxSolid({0.6 * a, -2.0, 0.4}, {2.0, 2.0, 0.6}));
  const double corner = std::numbers::pi * kLuminance * parallelCornerFactor(a, 1, 1);
  EXPECT_NEAR(exactAtOrigin(scene), corner, kDoubleRounding * corner);

  Scene centred;
  centred.sources.push_back(ceilingRect(-1.0, -1.0, 1.0, 1.0, 2.0, kLuminance));
  // Overlapping and flush shadows: each box hides x > h, x < -h, y > h or y < -h on the source
  // (h = a/2). A segment to (x, y, 2) runs through heights 0.9-1.0 at 0.45x-0.5x, through
  // 1.0-1.1 at 0.5y-0.55y.
  const double h = 0.5 * a;
  centred.solids.push_back(boxSolid({0.5 * h, -3.0, 0.9}, {3.0, 3.0, 1.0}));
  centred.solids.push_back(boxSolid({-3.0, -3.0, 0.9}, {-0.5 * h, 3.0, 1.0}));
  centred.solids.push_back(boxSolid({-3.0, 0.55 * h, 1.0}, {3.0, 3.0, 1.1}));
  centred.solids.push_back(boxSolid({-3.0, -3.0, 1.0}, {3.0, -0.55 * h, 1.1}));
  // Each height-2 quadrant square h × h with its corner over the point: four corner factors.
  const double square = 4.0 * std::numbers::pi * kLuminance * parallelCornerFactor(h, h, 2.0);
  EXPECT_NEAR(exactAtOrigin(centred), square, kDoubleRounding * square);
}

TEST(ExactIlluminance, TouchingAndOwnSolidsDoNotShade) {
  Scene scene;
  scene.sources.push_back(ceilingRect(0.0, 0.0, 1.0, 1.0, 1.0, kLuminance));
  scene.solids.push_back(boxSolid({-3.0, -3.0, 1.0}, {3.0, 3.0, 1.2}, "ceiling"));
  scene.solids.push_back(boxSolid({-3.0, -3.0, -0.2}, {3.0, 3.0, 0.0}, "floor"));
  scene.solids.push_back(boxSolid({-1.0, -1.0, 0.0}, {0.0, 0.0, 0.5}, "stool"));
  for (int solid : {-1, 1})
    EXPECT_NEAR(exactAt(scene, {Vec3::Zero(), Vec3::UnitZ(), solid}), cornerSquare(),
                kDoubleRounding * cornerSquare())
        << "solid " << solid;
  // Under a cabinet standing on the floor: every segment to the source runs through it.
  scene.solids.push_back(boxSolid({-0.5, -0.5, 0.0}, {0.5, 0.5, 0.7}, "cabinet"));
  EXPECT_EQ(exactAt(scene, {Vec3::Zero(), Vec3::UnitZ(), 1}), 0.0);
}

// On scenes without closed forms (penumbrae of several solids, reveals flush with windows,
// polyhedron sources) the two references agree to the sampled one's error at n = 256 (2e-5 of
// E_unoccluded; reference_illuminance.cpp).
void expectReferencesAgree(const std::string& file, std::size_t stride) {
  const Scene scene = loadScene(file);
  std::vector<SamplePoint> points;
  for (const CalculationGrid& grid : scene.grids) {
    const GridSamples samples = gridSamples(scene, grid);
    for (std::size_t i = 0; i < samples.points.size(); i += stride)
      if (samples.inside[i] < 0) points.push_back(samples.points[i]);
  }
  Scene open = scene;
  open.solids.clear();
  const std::vector<double> exact = exactIlluminance(scene, points)[0];
  const std::vector<double> unoccluded = exactIlluminance(open, points)[0];
  const std::vector<double> sampled = referenceIlluminance(scene, points, 256);
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double error = std::abs(exact[i] - sampled[i]) / unoccluded[i];
    worst = std::max(worst, error);
    EXPECT_LE(error, 2e-5) << file << " at (" << points[i].position.transpose() << ")";
  }
  std::printf("%s: %zu points, max |exact - sampled| / E_unoccluded = %.2e\n", file.c_str(),
              points.size(), worst);
}

TEST(ExactIlluminance, AgreesWithTheSampledReferenceOnTheCie171Scenes) {
  for (const char* name : {"tc5.3", "tc5.6", "tc5.7", "tc5.11"})
    expectReferencesAgree(
        PENUMBRA_SOURCE_DIR "/tests/validation/cie171/" + std::string(name) + ".yaml", 1);
}

TEST(ExactIlluminance, AgreesWithTheSampledReferenceOnTheOffice) {
  expectReferencesAgree(PENUMBRA_SOURCE_DIR "/data/office.yaml", 3);
}

}  // namespace
}  // namespace penumbra
