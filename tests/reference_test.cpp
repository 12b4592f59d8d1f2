// The host reference against closed forms: it is the oracle the kernel is held against, so it
// must itself be checked against something that shares no code with either.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "reference/reference_illuminance.hpp"
#include "test_scenes.hpp"

namespace penumbra {
namespace {

using testing::boxSolid;
using testing::ceilingRect;
using testing::parallelCornerFactor;
using testing::perpendicularFactor;

constexpr double kLuminance = 1000.0;  // cd/m²

// A unit square 1 m above the origin with its corner over the point (configuration-factor
// catalogue: X = Y = 1).
Scene cornerSquareScene() {
  Scene scene;
  scene.sources.push_back(ceilingRect(0.0, 0.0, 1.0, 1.0, 1.0, kLuminance));
  return scene;
}

double cornerSquareExact() {
  return std::numbers::pi * kLuminance * parallelCornerFactor(1, 1, 1);
}

double referenceAtOrigin(const Scene& scene, int n) {
  const SamplePoint origin{Vec3::Zero(), Vec3::UnitZ(), -1};
  return referenceIlluminance(scene, std::span(&origin, 1), n).at(0);
}

// Lambert's contour integral for a polygon wholly in front of p and unoccluded: a third,
// independent way to the exact value for shapes the catalogue does not list.
double contourIlluminance(const ConvexPolygon& polygon, double luminance, const Vec3& p,
                          const Vec3& n) {
  const auto& v = polygon.vertices();
  double sum = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3 a = v[i] - p, b = v[(i + 1) % v.size()] - p;
    const Vec3 c = a.cross(b);
    sum += std::atan2(c.norm(), a.dot(b)) * n.dot(c.normalized());
  }
  return 0.5 * luminance * std::fabs(sum);
}

TEST(ReferenceIlluminance, ParallelSquareWithCornerOverThePoint) {
  const double exact = cornerSquareExact();
  EXPECT_NEAR(referenceAtOrigin(cornerSquareScene(), 1024), exact, 1e-6 * exact);
}

TEST(ReferenceIlluminance, ConvergesAsNGrows) {
  const Scene scene = cornerSquareScene();
  const double exact = cornerSquareExact();
  const double coarse = std::fabs(referenceAtOrigin(scene, 32) - exact);
  const double fine = std::fabs(referenceAtOrigin(scene, 256) - exact);
  EXPECT_LT(fine, coarse);
  // The midpoint rule is second order: 8× finer, about 64× smaller error.
  EXPECT_LT(fine, coarse / 16.0);
}

TEST(ReferenceIlluminance, PerpendicularRectangle) {
  // Rectangle 0 <= x <= 2, 0 <= z <= 1.5 in the plane y = 1, emitting towards -y.
  Scene scene;
  scene.sources.push_back(testing::areaSource(
      {{0.0, 1.0, 0.0}, {2.0, 1.0, 0.0}, {2.0, 1.0, 1.5}, {0.0, 1.0, 1.5}}, kLuminance));
  ASSERT_LT(scene.sources[0].faces[0].normal().y(), -0.99);
  const double exact = std::numbers::pi * kLuminance * perpendicularFactor(2.0, 1.0, 1.5);
  EXPECT_NEAR(referenceAtOrigin(scene, 512), exact, 1e-5 * exact);
}

TEST(ReferenceIlluminance, TiltedHexagonMatchesTheContourIntegral) {
  // Not axis-aligned and not a quadrilateral: exercises the fan triangulation.
  std::vector<Vec3> hexagon;
  const Vec3 centre(0.3, -0.2, 2.0);
  const Vec3 u = Vec3(1.0, 0.0, 0.4).normalized(), w = Vec3(0.0, 1.0, -0.3).normalized();
  for (int i = 0; i < 6; ++i) {
    const double a = -2.0 * std::numbers::pi * i / 6;  // clockwise seen from above
    hexagon.push_back(centre + 0.7 * (std::cos(a) * u + std::sin(a) * w));
  }
  const ConvexPolygon polygon(hexagon);
  ASSERT_LT(polygon.normal().z(), 0.0);  // emits down, towards the point
  Scene scene;
  scene.sources.push_back(testing::areaSource(hexagon, kLuminance));
  const Vec3 normal = Vec3(0.2, 0.1, 1.0).normalized();
  const SamplePoint point{Vec3::Zero(), normal, -1};
  const double exact = contourIlluminance(polygon, kLuminance, Vec3::Zero(), normal);
  EXPECT_NEAR(referenceIlluminance(scene, std::span(&point, 1), 256).at(0), exact, 1e-4 * exact);
}

TEST(ReferenceIlluminance, BoxBetweenPointAndSourceGivesZero) {
  Scene scene = cornerSquareScene();
  scene.solids.push_back(boxSolid({-1.0, -1.0, 0.4}, {2.0, 2.0, 0.6}));
  EXPECT_EQ(referenceAtOrigin(scene, 64), 0.0);
}

TEST(ReferenceIlluminance, BoxBesideThePathDoesNotShade) {
  Scene scene = cornerSquareScene();
  scene.solids.push_back(boxSolid({-2.0, -2.0, 0.0}, {-0.5, -0.5, 3.0}));
  const double exact = cornerSquareExact();
  EXPECT_NEAR(referenceAtOrigin(scene, 256), exact, 1e-4 * exact);
}

TEST(ReferenceIlluminance, SourceFlushInASlabAndPointOnTheFloorAreNotShaded) {
  // Touching is not blocking: the ceiling slab's lower face holds the source, the floor slab's
  // upper face holds the point, and a box stands on the floor beside the point.
  Scene scene = cornerSquareScene();
  scene.solids.push_back(boxSolid({-3.0, -3.0, 1.0}, {3.0, 3.0, 1.2}, "ceiling"));
  scene.solids.push_back(boxSolid({-3.0, -3.0, -0.2}, {3.0, 3.0, 0.0}, "floor"));
  scene.solids.push_back(boxSolid({-1.0, -1.0, 0.0}, {0.0, 0.0, 0.5}, "stool"));
  const double exact = cornerSquareExact();
  for (int solid : {-1, 1}) {
    const SamplePoint point{Vec3::Zero(), Vec3::UnitZ(), solid};
    EXPECT_NEAR(referenceIlluminance(scene, std::span(&point, 1), 256).at(0), exact, 1e-4 * exact)
        << "solid " << solid;
  }
}

TEST(ReferenceIlluminance, ThePointsOwnSolidNeverShadesIt) {
  // A point on the lower face of a slab looking down at a source below: the slab lies behind it.
  // Marked as lying on the slab, it must see the source; a point inside the slab with the same
  // mark too (the solid is skipped altogether), but not when unmarked.
  Scene scene;
  scene.sources.push_back(testing::areaSource(
      {{0.0, 0.0, -1.0}, {1.0, 0.0, -1.0}, {1.0, 1.0, -1.0}, {0.0, 1.0, -1.0}}, kLuminance));
  scene.solids.push_back(boxSolid({-2.0, -2.0, 0.0}, {2.0, 2.0, 0.5}, "slab"));
  const double exact = cornerSquareExact();
  const SamplePoint inside{Vec3(0.0, 0.0, 0.25), -Vec3::UnitZ(), 0};
  const SamplePoint unmarked{Vec3(0.0, 0.0, 0.25), -Vec3::UnitZ(), -1};
  const auto marked = referenceIlluminance(scene, std::span(&inside, 1), 128).at(0);
  EXPECT_NEAR(marked, std::numbers::pi * kLuminance * parallelCornerFactor(1, 1, 1.25),
              1e-3 * exact);
  EXPECT_EQ(referenceIlluminance(scene, std::span(&unmarked, 1), 128).at(0), 0.0);
}

TEST(ReferenceIlluminance, APointUnderABoxStandingOnItsFloorIsDark) {
  // The point touches the box's lower face: every segment to the source runs through the box.
  Scene scene = cornerSquareScene();
  scene.solids.push_back(boxSolid({-3.0, -3.0, -0.2}, {3.0, 3.0, 0.0}, "floor"));
  scene.solids.push_back(boxSolid({-0.5, -0.5, 0.0}, {0.5, 0.5, 0.7}, "cabinet"));
  const SamplePoint point{Vec3::Zero(), Vec3::UnitZ(), 0};
  EXPECT_EQ(referenceIlluminance(scene, std::span(&point, 1), 64).at(0), 0.0);
}

TEST(ReferenceIlluminance, OccluderOverHalfTheSourceHalvesE) {
  // A slab over x > 0 between the point and a square centred above it hides exactly half.
  Scene scene;
  scene.sources.push_back(ceilingRect(-1.0, -1.0, 1.0, 1.0, 2.0, kLuminance));
  const double open = referenceAtOrigin(scene, 256);
  scene.solids.push_back(boxSolid({0.0, -3.0, 1.0}, {3.0, 3.0, 1.5}));
  EXPECT_NEAR(referenceAtOrigin(scene, 256), 0.5 * open, 1e-4 * open);
}

TEST(ReferenceIlluminance, AShadowEdgeParallelToTheSourceEdgesIsResolved) {
  // A slab over x >= 0.6·a between heights 0.4 and 0.6 hides the part x > a of the unit square
  // at height 1 (a segment to (x, y, 1) crosses height 0.6 at 0.6·x). The visible part is the
  // a × 1 rectangle (a = 0.4713, off any simple fraction) with its corner over the point: a closed
  // form again. Shadow edges along the source's edges are the usual case in buildings and must not
  // cost accuracy.
  Scene scene = cornerSquareScene();
  scene.solids.push_back(boxSolid({0.6 * 0.4713, -2.0, 0.4}, {2.0, 2.0, 0.6}));
  const double exact = std::numbers::pi * kLuminance * parallelCornerFactor(0.4713, 1, 1);
  EXPECT_NEAR(referenceAtOrigin(scene, 1024), exact, 1e-5 * exact);
  const double coarse = std::fabs(referenceAtOrigin(scene, 32) - exact);
  const double fine = std::fabs(referenceAtOrigin(scene, 256) - exact);
  EXPECT_LT(fine, coarse / 16.0);
}

TEST(ReferenceIlluminance, SourcesAddUpAndBackFacingOnesGiveNothing) {
  Scene scene = cornerSquareScene();
  // The same square turned to emit upwards: the point is behind it.
  scene.sources.push_back(testing::areaSource(
      {{0.0, 0.0, 1.0}, {1.0, 0.0, 1.0}, {1.0, 1.0, 1.0}, {0.0, 1.0, 1.0}}, kLuminance));
  // The neighbouring unit square: by symmetry the same E.
  scene.sources.push_back(ceilingRect(-1.0, 0.0, 0.0, 1.0, 1.0, kLuminance));
  const double exact = cornerSquareExact();
  EXPECT_NEAR(referenceAtOrigin(scene, 256), 2.0 * exact, 2e-4 * exact);
}

TEST(ReferenceIlluminance, ResultsDoNotDependOnTheThreadSchedule) {
  Scene scene = cornerSquareScene();
  scene.solids.push_back(boxSolid({0.3, 0.3, 0.4}, {0.6, 0.6, 0.6}));
  const std::vector<SamplePoint> points = testing::floorLine(-0.5, 1.5, 9);
  const auto first = referenceIlluminance(scene, points, 128);
  const auto second = referenceIlluminance(scene, points, 128);
  EXPECT_EQ(first, second);  // bitwise
}

}  // namespace
}  // namespace penumbra
