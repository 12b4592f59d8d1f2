// The illuminance kernel on PoCL against closed forms and invariants.
#include <gtest/gtest.h>

#include <numbers>
#include <random>

#include "engine/illuminance_engine.hpp"
#include "test_device.hpp"
#include "test_scenes.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;
constexpr double kPi = std::numbers::pi;
// Closed forms are met to 1e-5 relative: float kernels, 2^-24 rounding per operation.
constexpr double kClosedFormRelative = 1e-5;

std::vector<double> kernelE(const Scene& scene, const std::vector<SamplePoint>& points) {
  IlluminanceEngine engine(cpuDevice(), scene);
  return engine.illuminance(points);
}

double kernelE(const Scene& scene, const SamplePoint& point) {
  return kernelE(scene, std::vector<SamplePoint>{point})[0];
}

TEST(ClosedForm, ParallelRectangleCornerOverPoint) {
  const double L = 1000.0;
  for (auto [a, b, c] :
       {std::tuple{1.0, 1.0, 1.0}, {0.6, 0.6, 2.2}, {3.0, 0.5, 0.4}, {0.1, 0.2, 5.0}}) {
    Scene scene;
    scene.sources.push_back(ceilingRect(0, 0, a, b, c, L));
    const double expected = kPi * L * parallelCornerFactor(a, b, c);
    const double e = kernelE(scene, SamplePoint{Vec3::Zero(), Vec3::UnitZ(), -1});
    EXPECT_NEAR(e, expected, kClosedFormRelative * expected) << a << " " << b << " " << c;
  }
}

TEST(ClosedForm, ParallelRectangleOffCornerBySuperposition) {
  const double L = 2500.0, h = 2.0;
  // The rectangle [-1, 2] × [-0.5, 1.5] seen from the origin: four corner rectangles.
  Scene scene;
  scene.sources.push_back(ceilingRect(-1, -0.5, 2, 1.5, h, L));
  const double f = parallelCornerFactor(1, 0.5, h) + parallelCornerFactor(2, 0.5, h) +
                   parallelCornerFactor(1, 1.5, h) + parallelCornerFactor(2, 1.5, h);
  const double e = kernelE(scene, SamplePoint{Vec3::Zero(), Vec3::UnitZ(), -1});
  EXPECT_NEAR(e, kPi * L * f, kClosedFormRelative * kPi * L * f);
  // A point outside the rectangle's shadow: [1, 3] × [0, 2] from the origin is
  // F(3, 2) - F(1, 2).
  Scene outside;
  outside.sources.push_back(ceilingRect(1, 0, 3, 2, h, L));
  const double g = parallelCornerFactor(3, 2, h) - parallelCornerFactor(1, 2, h);
  const double e2 = kernelE(outside, SamplePoint{Vec3::Zero(), Vec3::UnitZ(), -1});
  EXPECT_NEAR(e2, kPi * L * g, kClosedFormRelative * kPi * L * g);
}

TEST(ClosedForm, PerpendicularRectangle) {
  const double L = 800.0;
  for (auto [a, b, c] : {std::tuple{1.0, 1.0, 1.0}, {2.0, 0.5, 3.0}, {0.3, 2.0, 0.7}}) {
    // Rectangle in the plane y = b emitting towards -y, 0 <= x <= a, 0 <= z <= c.
    Scene scene;
    scene.sources.push_back(areaSource({{0, b, 0}, {a, b, 0}, {a, b, c}, {0, b, c}}, L));
    ASSERT_GT(scene.sources[0].faces[0].normal().dot(-Vec3::UnitY()), 0.99);
    const double expected = kPi * L * perpendicularFactor(a, b, c);
    const double e = kernelE(scene, SamplePoint{Vec3::Zero(), Vec3::UnitZ(), -1});
    EXPECT_NEAR(e, expected, kClosedFormRelative * expected) << a << " " << b << " " << c;
  }
}

TEST(ClosedForm, RegularPolygonAndDisk) {
  const double L = 1200.0, R = 0.8, h = 1.7;
  const int sides = 256;
  Scene scene;
  scene.sources.push_back(regularPolygonSource(sides, R, h, L));
  const double e = kernelE(scene, SamplePoint{Vec3::Zero(), Vec3::UnitZ(), -1});
  // The polygon's own closed form on its axis: each edge (apothem r, half-length s) subtends
  // 2·atan(s/d) at distance d = sqrt(h² + r²), in a plane whose normal has n-component r/d.
  const double r = R * std::cos(kPi / sides), s = R * std::sin(kPi / sides);
  const double d = std::sqrt(h * h + r * r);
  const double polygon = 0.5 * L * sides * 2.0 * std::atan(s / d) * r / d;
  EXPECT_NEAR(e, polygon, kClosedFormRelative * polygon);
  // The disk formula, within the polygon's approximation error: the inscribed polygon's area
  // falls short of the disk's by 1 - sin(2π/N)/(2π/N); E differs by less than twice that.
  const double disk = kPi * L * R * R / (h * h + R * R);
  const double areaDeficit = 1.0 - std::sin(2 * kPi / sides) / (2 * kPi / sides);
  EXPECT_LT(e, disk);
  EXPECT_NEAR(e, disk, 2.0 * areaDeficit * disk);
}

TEST(Horizon, SourceCutByTheReceivingPlane) {
  // Receiver normal +x at the origin; a 2 × 2 ceiling square at z = 1 centred over it. The
  // receiver's plane x = 0 cuts it in half (Nishita type B): the lit half is two perpendicular
  // rectangles of a = 1 (along y), b = 1 (height), c = 1 (along x).
  const double L = 1000.0;
  Scene scene;
  scene.sources.push_back(ceilingRect(-1, -1, 1, 1, 1.0, L));
  const SamplePoint p{Vec3::Zero(), Vec3::UnitX(), -1};
  const double expected = 2.0 * kPi * L * perpendicularFactor(1, 1, 1);
  EXPECT_NEAR(kernelE(scene, p), expected, kClosedFormRelative * expected);
  // The same as the already-clipped polygon, for tilted normals too.
  for (double tilt : {0.2, 0.7, 1.2}) {
    const Vec3 n(std::sin(tilt), 0, std::cos(tilt));
    const SamplePoint q{Vec3::Zero(), n, -1};
    // Clip by hand: keep n·x >= 0 on z = 1, i.e. x >= -cos/sin.
    const double xCut = -std::cos(tilt) / std::sin(tilt);
    Scene clipped;
    clipped.sources.push_back(ceilingRect(std::max(-1.0, xCut), -1, 1, 1, 1.0, L));
    const double reference = kernelE(clipped, q);
    EXPECT_NEAR(kernelE(scene, q), reference, kClosedFormRelative * reference) << tilt;
  }
}

TEST(Horizon, SourceBehindThePointGivesNothing) {
  Scene scene;
  scene.sources.push_back(ceilingRect(-1, -1, 1, 1, 1.0, 1000.0));
  EXPECT_EQ(kernelE(scene, SamplePoint{Vec3::Zero(), -Vec3::UnitZ(), -1}), 0.0);
  // Above the source plane: behind its emitting side.
  EXPECT_EQ(kernelE(scene, SamplePoint{Vec3(0, 0, 2), Vec3::UnitZ(), -1}), 0.0);
}

TEST(Properties, SplittingASourceSumsToTheWhole) {
  const double L = 1500.0;
  Scene whole, left, right;
  whole.sources.push_back(ceilingRect(-1, -0.5, 1.5, 0.5, 2.0, L));
  left.sources.push_back(ceilingRect(-1, -0.5, 0.3, 0.5, 2.0, L));
  right.sources.push_back(ceilingRect(0.3, -0.5, 1.5, 0.5, 2.0, L));
  for (Scene* s : {&whole, &left, &right})
    s->solids.push_back(boxSolid({-0.2, -0.2, 1.0}, {0.4, 0.3, 1.2}));
  const auto points = floorLine(-1.5, 2.0, 64);
  const auto w = kernelE(whole, points), l = kernelE(left, points), r = kernelE(right, points);
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_NEAR(w[i], l[i] + r[i], kClosedFormRelative * w[i] + 1e-6) << i;
}

TEST(Properties, AddingAnOccluderNeverRaisesIlluminance) {
  std::mt19937 random(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Scene scene;
  scene.sources.push_back(ceilingRect(-0.5, -0.5, 0.5, 0.5, 3.0, 2000.0));
  const auto points = floorLine(-2.0, 2.0, 40, 0.1);
  std::vector<double> before = kernelE(scene, points);
  for (int k = 0; k < 6; ++k) {
    const Vec3 c(u(random) * 2 - 1, u(random) * 2 - 1, 0.5 + 2.0 * u(random));
    const Vec3 half(0.05 + 0.3 * u(random), 0.05 + 0.3 * u(random), 0.02 + 0.2 * u(random));
    scene.solids.push_back(boxSolid(c - half, c + half));
    const std::vector<double> after = kernelE(scene, points);
    for (std::size_t i = 0; i < points.size(); ++i)
      EXPECT_LE(after[i], before[i] * (1 + kClosedFormRelative) + 1e-6) << k << " " << i;
    before = after;
  }
}

TEST(Properties, UmbraIsZeroAndDistantPointsAreUnoccluded) {
  Scene scene;
  scene.sources.push_back(ceilingRect(-0.3, -0.3, 0.3, 0.3, 3.0, 1000.0));
  scene.solids.push_back(boxSolid({-1, -1, 1.0}, {1, 1, 1.1}));
  EXPECT_EQ(kernelE(scene, SamplePoint{Vec3::Zero(), Vec3::UnitZ(), -1}), 0.0);
  Scene open;
  open.sources = scene.sources;
  const SamplePoint far{Vec3(6, 0, 0), Vec3::UnitZ(), -1};
  EXPECT_NEAR(kernelE(scene, far), kernelE(open, far), kClosedFormRelative * kernelE(open, far));
}

TEST(Properties, ThePointsOwnSolidNeverShadesIt) {
  // A point on top of a desk, with the desk listed as its solid, sees the whole source.
  Scene scene;
  scene.sources.push_back(ceilingRect(-0.3, -0.3, 0.3, 0.3, 3.0, 1000.0));
  scene.solids.push_back(boxSolid({-1, -1, 0.72}, {1, 1, 0.75}, "desk"));
  Scene open;
  open.sources = scene.sources;
  const SamplePoint onDesk{Vec3(0.2, 0.1, 0.75), Vec3::UnitZ(), 0};
  EXPECT_NEAR(kernelE(scene, onDesk), kernelE(open, onDesk), 1e-6 * kernelE(open, onDesk));
}

}  // namespace
}  // namespace penumbra
