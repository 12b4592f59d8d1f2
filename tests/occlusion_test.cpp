// Occlusion by the visible-segment method (kernel, float) against the independent reference
// (host, double, ~n² lattice samples per face with exact ray tests).
// Criterion: max |E − E_ref| ≤ 2e-3 × E_unoccluded at every point, with n ≥ 1024
// (256 in the sanitizer build: tests/sanitized_build.hpp). That criterion is the sampled
// reference's; against the exact reference (reference/exact_illuminance: the occluders' shadows
// projected on each source's plane, double) the kernel is also held to kKernelRelative
// (1e-5) of E_unoccluded, which the float kernel meets with a margin of ten or more everywhere
// but at points on a solid's vertical face (PointsTouchingAnotherSolid).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "engine/illuminance_engine.hpp"
#include "geometry/tolerance.hpp"
#include "reference/exact_illuminance.hpp"
#include "reference/reference_illuminance.hpp"
#include "sanitized_build.hpp"
#include "test_device.hpp"
#include "test_scenes.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;
constexpr int kReferenceN = 1024;
constexpr double kOcclusionTolerance = 2e-3;  // of the unoccluded value at the same point

struct Comparison {
  double worst = 0.0;       // max |E − E_ref| / E_unoccluded
  double worstExact = 0.0;  // max |E − E_exact| / E_unoccluded
  int shaded = 0;           // points where the occluders remove more than 1 % of the light
  int umbra = 0;            // points with E_ref = 0 although the source is in front
};

// Compares kernel and reference at every point and counts the shadow classes it went through,
// so that a scene meant to test penumbrae really has some.
Comparison compare(const Scene& scene, const std::vector<SamplePoint>& points,
                   double exactTolerance = Tolerance::kKernelRelative) {
  Scene open = scene;
  open.solids.clear();
  IlluminanceEngine engine(cpuDevice(), scene);
  IlluminanceEngine openEngine(cpuDevice(), open);
  const std::vector<double> e = engine.illuminance(points);
  const std::vector<double> unoccluded = openEngine.illuminance(points);
  const std::vector<double> reference =
      referenceIlluminance(scene, points, referenceSamples(kReferenceN));
  const std::vector<double> exact = exactIlluminance(scene, points)[0];
  Comparison c;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (unoccluded[i] <= 0.0) continue;
    const double error = std::abs(e[i] - reference[i]) / unoccluded[i];
    EXPECT_LE(error, kOcclusionTolerance)
        << "point " << points[i].position.transpose() << ": E = " << e[i] << " lx, reference "
        << reference[i] << " lx, unoccluded " << unoccluded[i] << " lx";
    c.worst = std::max(c.worst, error);
    const double exactError = std::abs(e[i] - exact[i]) / unoccluded[i];
    EXPECT_LE(exactError, exactTolerance)
        << "point " << points[i].position.transpose() << ": E = " << e[i] << " lx, exact "
        << exact[i] << " lx, unoccluded " << unoccluded[i] << " lx";
    c.worstExact = std::max(c.worstExact, exactError);
    if (std::getenv("PENUMBRA_TEST_VERBOSE"))
      std::printf("    %s  E %.6g  ref %.6g  rel %.2e\n",
                  fmt::format("{:.3f} {:.3f} {:.3f}", points[i].position.x(),
                              points[i].position.y(), points[i].position.z())
                      .c_str(),
                  e[i], reference[i], error);
    if (reference[i] < 0.99 * unoccluded[i]) ++c.shaded;
    if (reference[i] == 0.0) ++c.umbra;
  }
  // Reported, not asserted beyond the criterion above: the figure for the closing note.
  std::printf(
      "  %zu points, %d shaded, %d in umbra, max |E - E_ref| / E_unoccluded = %.2e, "
      "max |E - E_exact| / E_unoccluded = %.2e\n",
      points.size(), c.shaded, c.umbra, c.worst, c.worstExact);
  return c;
}

std::vector<SamplePoint> floorGrid(double x0, double x1, double y0, double y1, int nx, int ny,
                                   int solid) {
  std::vector<SamplePoint> points;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      points.push_back({Vec3(x0 + (x1 - x0) * (i + 0.5) / nx, y0 + (y1 - y0) * (j + 0.5) / ny, 0),
                        Vec3::UnitZ(), solid});
  return points;
}

Scene panelOverFloor() {
  Scene scene;
  scene.sources.push_back(ceilingRect(-0.5, -0.5, 0.5, 0.5, 3.0, 1000.0));
  scene.solids.push_back(boxSolid({-3, -3, -0.2}, {3, 3, 0}, "floor"));
  return scene;
}

TEST(Occlusion, BoxBetweenPanelAndFloor) {
  Scene scene = panelOverFloor();
  scene.solids.push_back(boxSolid({-0.4, -0.3, 1.0}, {0.4, 0.3, 1.3}, "box"));
  const Comparison c = compare(scene, floorGrid(-2, 2, -1.5, 1.5, 9, 7, 0));
  EXPECT_GT(c.shaded, 5);
  EXPECT_GT(c.umbra, 0);
}

TEST(Occlusion, TwoTouchingBoxesSideBySide) {
  Scene scene = panelOverFloor();
  scene.solids.push_back(boxSolid({-0.5, -0.3, 1.0}, {0.0, 0.3, 1.4}, "left"));
  scene.solids.push_back(boxSolid({0.0, -0.3, 1.0}, {0.5, 0.3, 1.4}, "right"));
  const Comparison c = compare(scene, floorGrid(-2, 2, -1.5, 1.5, 9, 7, 0));
  EXPECT_GT(c.shaded, 5);
  EXPECT_GT(c.umbra, 0);
}

TEST(Occlusion, DuplicatedOccluderCountsOnce) {
  Scene scene = panelOverFloor();
  scene.solids.push_back(boxSolid({-0.3, -0.2, 1.5}, {0.2, 0.3, 1.8}, "a"));
  scene.solids.push_back(boxSolid({-0.3, -0.2, 1.5}, {0.2, 0.3, 1.8}, "b"));
  const Comparison c = compare(scene, floorGrid(-1.5, 1.5, -1.5, 1.5, 7, 7, 0));
  EXPECT_GT(c.shaded, 5);
}

TEST(Occlusion, OccluderEdgeCollinearWithSourceEdge) {
  // The box touches the source plane z = 3 and its top edge x = 0.5, z = 3 lies on the
  // source's edge line.
  Scene scene = panelOverFloor();
  scene.solids.push_back(boxSolid({0.5, -1.0, 2.6}, {1.0, 1.0, 3.0}, "beam"));
  const Comparison c = compare(scene, floorGrid(-2, 2, -1.0, 1.0, 9, 5, 0));
  EXPECT_GT(c.shaded, 3);
}

TEST(Occlusion, SourceEdgeAndOccluderEdgeWithinTheTieToleranceOfOnePlane) {
  // A wall element (0.25 × 0.15 m on the wall y = 0) seen from the floor past a desk's front
  // bottom edge: both edges run along x, so one plane through a floor point holds both at
  // y = lineY. The source is whole for y ≤ lineY and loses a sliver along its top edge beyond.
  // For about a µm past lineY the two edges' planes are within the tie tolerance of each other,
  // yet each edge's ends lie at a different sine from the other's plane (their distances from
  // the planes' common line over their lengths differ): the tie rule must take the pair as tied
  // at both edges or at neither, or the contour is left open (the top edge covered, the desk's
  // edge dropped as tied: 13 times the element's E 14 µm past lineY with a tie tolerance of
  // 1e-5, 1.4 µm with 1e-6). Every 0.05 µm over 6 µm, on the eight-lane, scalar and plain paths,
  // against the exact reference, and against the closed form (two perpendicular rectangles)
  // where the source is whole.
  const double x0 = 3.75, x1 = 4.0, z0 = 2.7, z1 = 2.85, luminance = 1000.0;
  const double deskY = 1.2, deskZ = 0.72, px = 3.786;
  Scene scene;
  scene.sources.push_back(
      areaSource({{x0, 0, z0}, {x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}}, luminance));
  scene.solids.push_back(boxSolid({3.4, deskY, deskZ}, {5.0, 2.0, 0.75}, "desk"));
  const double lineY = z1 * deskY / (z1 - deskZ);
  std::vector<SamplePoint> points;
  for (int k = -20; k <= 100; ++k)
    points.push_back({Vec3(px, lineY + 0.05e-6 * k, 0.0), Vec3::UnitZ(), -1});
  const std::vector<double> exact = exactIlluminance(scene, points)[0];
  for (const bool lanes : {true, false})
    for (const bool culling : {true, false}) {
      if (!culling && !lanes) continue;  // the plain path has no lanes
      EngineOptions options;
      options.culling = culling;
      options.vectorPenumbra = lanes;
      IlluminanceEngine engine(cpuDevice(), scene, options);
      const std::vector<double> e = engine.illuminance(points);
      for (std::size_t i = 0; i < points.size(); ++i) {
        const double y = points[i].position.y();
        const double whole =
            std::numbers::pi * luminance *
            (perpendicularFactor(x1 - px, y, z1) - perpendicularFactor(x1 - px, y, z0) +
             perpendicularFactor(px - x0, y, z1) - perpendicularFactor(px - x0, y, z0));
        // Within the tie band the kernel keeps or drops a sliver at most kKernelTie wide (in
        // sine) along the top edge: at most that over the source's angular height of E, twice
        // for the cosines across it (4.3e-5 here), and no less than the kernel's float error
        // elsewhere (kKernelRelative of E).
        const double height = std::atan(z1 / y) - std::atan(z0 / y);
        const double bound =
            std::max(2.0 * Tolerance::kKernelTie / height, double(Tolerance::kKernelRelative)) *
            whole;
        EXPECT_NEAR(e[i], exact[i], bound) << "y - lineY = " << (y - lineY) * 1e6 << " µm, culling "
                                           << culling << ", lanes " << lanes;
        if (y <= lineY) {
          EXPECT_NEAR(e[i], whole, Tolerance::kKernelRelative * whole)
              << "y - lineY = " << (y - lineY) * 1e6 << " µm";
        }
      }
    }
}

TEST(Occlusion, OccluderCrossingTheSourcePlane) {
  // A pendant box through the panel's plane: only its part below z = 3 can shade.
  Scene scene = panelOverFloor();
  scene.solids.push_back(boxSolid({-0.2, -0.1, 2.4}, {0.1, 0.2, 3.5}, "pendant"));
  const Comparison c = compare(scene, floorGrid(-2, 2, -1.5, 1.5, 9, 7, 0));
  EXPECT_GT(c.shaded, 5);
}

TEST(Occlusion, WindowInAThickWallTheRevealShades) {
  // Wall y0 of a room (interior y > 0), 0.3 m thick, with a 1.2 × 1.0 m opening at sill
  // 0.9 m; the sky fills the opening on the wall's outer face y = -0.3, emitting into the room.
  Scene scene;
  const double t = 0.3, x0 = 1.0, x1 = 2.2, z0 = 0.9, z1 = 1.9;
  scene.solids.push_back(boxSolid({-t, -t, 0}, {x0, 0, 3}, "wall-left"));
  scene.solids.push_back(boxSolid({x1, -t, 0}, {4, 0, 3}, "wall-right"));
  scene.solids.push_back(boxSolid({x0, -t, 0}, {x1, 0, z0}, "wall-below"));
  scene.solids.push_back(boxSolid({x0, -t, z1}, {x1, 0, 3}, "wall-above"));
  scene.solids.push_back(boxSolid({-t, -t, -0.2}, {4, 4, 0}, "floor"));
  // Counter-clockwise about +y.
  scene.sources.push_back(
      areaSource({{x0, -t, z0}, {x0, -t, z1}, {x1, -t, z1}, {x1, -t, z0}}, 3000));
  ASSERT_GT(scene.sources[0].faces[0].normal().y(), 0.99);
  std::vector<SamplePoint> points = floorGrid(0.0, 3.5, 0.1, 3.0, 8, 6, 4);
  // Close to the wall the floor sees the sky only over the sill: umbra.
  for (const SamplePoint& p : floorLine(0.5, 3.0, 6, 0.1, 0.0, 4)) points.push_back(p);
  // Points on the side reveal and the sill see the sky at grazing angles.
  points.push_back({Vec3(x0, -0.1, 1.4), Vec3::UnitX(), 0});
  points.push_back({Vec3(1.6, -0.1, z0), Vec3::UnitZ(), 2});
  const Comparison c = compare(scene, points);
  EXPECT_GT(c.shaded, 10);
  EXPECT_GT(c.umbra, 0);
}

TEST(Occlusion, FlushCeilingPanelIsNotShadedByTheCeilingSlab) {
  // The panel lies in the slab's underside (CIE 171 TC 5.3): the slab, clipped to the panel's
  // front half-space, has no volume left and must not shade anything.
  Scene scene;
  scene.sources.push_back(ceilingRect(1.5, 1.5, 2.5, 2.5, 3.0, 1000.0));
  scene.solids.push_back(boxSolid({-0.2, -0.2, 3.0}, {4.2, 4.2, 3.2}, "ceiling"));
  scene.solids.push_back(boxSolid({-0.2, -0.2, -0.2}, {4.2, 4.2, 0.0}, "floor"));
  scene.solids.push_back(boxSolid({-0.2, -0.2, 0.0}, {4.2, 0.0, 3.0}, "wall-y0"));
  std::vector<SamplePoint> points = floorGrid(0, 4, 0, 4, 6, 6, 1);
  for (double z : {0.25, 1.25, 2.25, 2.75}) points.push_back({Vec3(2, 0, z), Vec3::UnitY(), 2});
  Scene open = scene;
  open.solids.clear();
  IlluminanceEngine engine(cpuDevice(), scene), openEngine(cpuDevice(), open);
  const auto e = engine.illuminance(points), unoccluded = openEngine.illuminance(points);
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_NEAR(e[i], unoccluded[i], 1e-6 * unoccluded[i]) << points[i].position.transpose();
  compare(scene, points);
}

TEST(Occlusion, PointsTouchingAnotherSolid) {
  // A cabinet standing on the floor: floor points under it are dark, points beside it are
  // shaded by it, and points on its side faces (listed as on the cabinet) see half the room.
  Scene scene = panelOverFloor();
  scene.solids.push_back(boxSolid({0.2, -0.4, 0.0}, {0.8, 0.4, 1.2}, "cabinet"));
  std::vector<SamplePoint> points = floorGrid(-1.0, 1.4, -0.8, 0.8, 12, 8, 0);
  for (double z : {0.1, 0.6, 1.1}) {
    points.push_back({Vec3(0.2, 0.0, z), -Vec3::UnitX(), 1});
    points.push_back({Vec3(0.5, -0.4, z), -Vec3::UnitY(), 1});
  }
  // On the cabinet's bottom edge, on the floor (the floor is its solid): a contact on an edge.
  points.push_back({Vec3(0.2, 0.1, 0.0), Vec3::UnitZ(), 0});
  // A point on a side face sees only the sliver of the panel above its horizon, and the kernel
  // errs most there (measured 1.3e-4 of E_unoccluded at (0.5, -0.4, 0.1), both references
  // agreeing to 1e-6): held to the 2e-3 criterion only.
  const Comparison c = compare(scene, points, kOcclusionTolerance);
  EXPECT_GT(c.umbra, 8);
  EXPECT_GT(c.shaded, 20);
}

TEST(Occlusion, PolyhedronSourceBehindABox) {
  // A luminous cube (every face emits) partly hidden by a box.
  Scene scene = panelOverFloor();
  scene.sources.clear();
  Source cube;
  cube.name = "cube";
  cube.shape = SourceShape::Polyhedron;
  const ConvexPolyhedron body = ConvexPolyhedron::box({-0.2, -0.2, 2.0}, {0.2, 0.2, 2.4});
  for (std::size_t f = 0; f < body.faces().size(); ++f)
    cube.faces.push_back(body.facePolygon(static_cast<int>(f)));
  cube.luminance = 1500;
  scene.sources.push_back(cube);
  scene.solids.push_back(boxSolid({0.1, -0.5, 1.2}, {0.6, 0.5, 1.4}, "shelf"));
  const Comparison c = compare(scene, floorGrid(-2, 2, -1.5, 1.5, 9, 7, 0));
  EXPECT_GT(c.shaded, 5);
}

}  // namespace
}  // namespace penumbra
