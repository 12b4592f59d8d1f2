// The field of interreflected light (radiosity/indirect_field.hpp) on a hand-made mesh with a
// known light: a linear light comes back exactly from the elements' fan triangles alone; a
// steep light comes back within the tolerance of its own value, with triangles cut where it
// bends; nothing is interpolated across a face edge; points on no element and in triangles
// still uneven at the depth limit are gathered exactly; the value at a point does not depend
// on the points asked for before it; with the defaults, triangles are cut to the least depth and
// the points along a face's edge are gathered exactly, or, given the scene's solids, along its
// concave edges only.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "radiosity/indirect_field.hpp"

namespace penumbra {
namespace {

// A 2 × 1 m floor (solid 0, face 0, z = 0) cut into 0.5 m squares, and a 1 × 1 m wall (solid 1,
// face 2, x = 2) beside it, cut into two squares, as interreflection's elements.
SurfaceMesh twoFaces() {
  SurfaceMesh mesh;
  const auto add = [&](std::vector<Vec3> v, int solid, int face) {
    SurfaceElement e;
    e.polygon = ConvexPolygon(std::move(v));
    e.solid = solid;
    e.face = face;
    e.area = e.polygon.area();
    mesh.elements.push_back(e);
  };
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 2; ++j) {
      const double x = 0.5 * i, y = 0.5 * j;
      add({{x, y, 0}, {x + 0.5, y, 0}, {x + 0.5, y + 0.5, 0}, {x, y + 0.5, 0}}, 0, 0);
    }
  for (int j = 0; j < 2; ++j) {
    const double y = 0.5 * j;
    add({{2, y, 0}, {2, y, 1}, {2, y + 0.5, 1}, {2, y + 0.5, 0}}, 1, 2);
  }
  return mesh;
}

struct Counted {
  std::function<Eigen::Vector3d(const SamplePoint&)> light;
  std::size_t calls = 0, points = 0;
  FieldGather gather() {
    return [this](std::span<const SamplePoint> at) {
      ++calls;
      points += at.size();
      std::vector<Eigen::Vector3d> e;
      for (const SamplePoint& p : at) e.push_back(light(p));
      return e;
    };
  }
};

std::vector<FacePoint> floorPoints(int n) {
  std::vector<FacePoint> points;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < 2 * n; ++i)
      points.push_back(FacePoint{Vec3((i + 0.5) / n, (j + 0.5) / n, 0.0), 0, 0});
  return points;
}

TEST(IndirectField, ALinearLightComesBackExactlyFromTheElementsTriangles) {
  Counted light{[](const SamplePoint& p) {
    const double x = p.position.x(), y = p.position.y();
    return Eigen::Vector3d(100 + 20 * x - 5 * y, 80 + 3 * y, 60 + 10 * x);
  }};
  const SurfaceMesh mesh = twoFaces();
  // The triangles alone: no least depth, no band gathered exactly.
  FieldOptions options;
  options.minDepth = 0;
  options.boundaryBand = 0.0;
  IndirectField field(mesh, 3.0, light.gather(), options);
  const std::vector<FacePoint> points = floorPoints(40);
  std::vector<float> channels(points.size() * 3);
  field.evaluate(points, channels);
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d truth = light.light(SamplePoint{points[i].position, Vec3::UnitZ(), 0});
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(channels[i * 3 + c] - truth[c]) / truth[c]);
  }
  // The floor's boundary nodes are gathered 30 µm inside (kNudgeInKernelTolerances at a 3 m
  // scene): the light's slope (under 25 lx/m) over that is below 3e-5 of its value.
  EXPECT_LE(worst, 3e-5);
  // 8 squares, 2 triangles each, none cut (their midpoints lie on the line between their
  // corners): the 5 × 9 lattice of corners and midpoints, the diagonals' among them.
  EXPECT_EQ(field.stats().triangles, 16u);
  EXPECT_EQ(field.stats().nodes, 45u);
  EXPECT_EQ(field.stats().pointsGathered, 0u);
}

TEST(IndirectField, ASteepLightIsCutDownToItsToleranceWithinEachFace) {
  // A bump 0.1 m wide on the floor, a different level on the wall: the wall never sees the
  // floor's values (its points are its own light exactly).
  Counted light{[](const SamplePoint& p) {
    if (p.solid == 1) return Eigen::Vector3d::Constant(500.0);
    const double r2 = (p.position - Vec3(0.8, 0.4, 0)).squaredNorm();
    return Eigen::Vector3d::Constant(100.0 + 50.0 * std::exp(-r2 / 0.01));
  }};
  const SurfaceMesh mesh = twoFaces();
  FieldOptions options;
  options.maxDepth = 8;
  options.minDepth = 0;
  options.boundaryBand = 0.0;
  IndirectField field(mesh, 3.0, light.gather(), options);
  std::vector<FacePoint> points = floorPoints(100);
  for (int j = 0; j < 20; ++j)
    for (int k = 0; k < 20; ++k)
      points.push_back(FacePoint{Vec3(2.0, (j + 0.5) / 20, (k + 0.5) / 20), 1, 2});
  std::vector<float> channels(points.size() * 3);
  field.evaluate(points, channels);
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const SamplePoint p{points[i].position, Vec3::UnitZ(), points[i].solid};
    const double truth = light.light(p)[1];
    worst = std::max(worst, std::abs(channels[i * 3 + 1] - truth) / truth);
  }
  EXPECT_LE(worst, options.tolerance);
  EXPECT_GT(field.stats().triangles, 16u + 4u);  // cut round the bump
  EXPECT_EQ(field.stats().pointsGathered, 0u);
  EXPECT_LT(field.stats().nodes, points.size() / 3);  // measured: 5 209 for 20 400 points

  // Asked again in another order, from a fresh field that saw other points first: the same
  // floats (the points are evaluated in parallel chunks, each chunk starting its search afresh).
  IndirectField again(mesh, 3.0, light.gather(), options);
  std::vector<float> first(3 * 5);
  again.evaluate(std::span(points).subspan(4000, 5), first);
  std::vector<FacePoint> reversed(points.rbegin(), points.rend());
  std::vector<float> other(reversed.size() * 3);
  again.evaluate(reversed, other);
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(other[(points.size() - 1 - i) * 3 + c], channels[i * 3 + c]) << i;
}

// The linear light of the band tests, and the floor's 40 × 80 points 0.025 m apart evaluated on
// a field over twoFaces() with the defaults: the worst relative error against the light and how
// many points lie within the band of the edges `fromEdge` measures.
Eigen::Vector3d linearLight(const SamplePoint& p) {
  const double x = p.position.x(), y = p.position.y();
  return Eigen::Vector3d(100 + 20 * x - 5 * y, 80 + 3 * y, 60 + 10 * x);
}

struct BandCheck {
  double worst = 0.0;
  std::size_t inBand = 0;
  IndirectFieldStats stats;
};

BandCheck floorInBand(const std::function<double(const Vec3&)>& fromEdge,
                      InsideSolid insideSolid = {}) {
  Counted light{linearLight};
  const FieldOptions options;
  const SurfaceMesh mesh = twoFaces();  // the field keeps a pointer to it
  IndirectField field(mesh, 3.0, light.gather(), options, std::move(insideSolid));
  const std::vector<FacePoint> points = floorPoints(40);
  std::vector<float> channels(points.size() * 3);
  field.evaluate(points, channels);
  BandCheck check;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& x = points[i].position;
    if (fromEdge(x) < options.boundaryBand) ++check.inBand;
    const Eigen::Vector3d truth = linearLight(SamplePoint{x, Vec3::UnitZ(), 0});
    for (int c = 0; c < 3; ++c)
      check.worst = std::max(check.worst, std::abs(channels[i * 3 + c] - truth[c]) / truth[c]);
  }
  check.stats = field.stats();
  return check;
}

// With the defaults: every triangle is cut to the least depth (a square's two fan triangles into
// 32 of 0.125 m legs) and the points within the band along the floor's edge are gathered one by
// one; the linear light still comes back from the triangles everywhere else.
TEST(IndirectField, TrianglesAreCutToTheLeastDepthAndTheFacesEdgeBandIsGathered) {
  ASSERT_EQ(FieldOptions{}.minDepth, 2);
  const BandCheck check = floorInBand([](const Vec3& x) {
    return std::min({x.x(), 2.0 - x.x(), x.y(), 1.0 - x.y()});
  });
  EXPECT_LE(check.worst, 3e-5);
  // The outer ring of points, 0.0125 m from the edge, and the next, 0.0375 m from it, lie in
  // the 0.04 m band.
  EXPECT_EQ(check.inBand, 2u * (80 + 40) * 2 - 16);
  EXPECT_EQ(check.stats.pointsGathered, check.inBand);
  EXPECT_EQ(check.stats.triangles, 16u * (1 + 4 + 16));
  // The lattice of the depth-2 triangles' corners and midpoints: every 0.0625 m.
  EXPECT_EQ(check.stats.nodes, 33u * 17u);
}

// Given the scene's solids (a floor slab under the floor, a wall slab behind the wall), the band
// runs only along the concave edge where the wall stands on the floor: the floor's three open
// edges are convex, nothing rises in front of the floor there, and their points come from the
// triangles like every other point.
TEST(IndirectField, WithTheScenesSolidsTheBandRunsAlongTheConcaveEdgesOnly) {
  const auto insideBox = [](const Vec3& p, const Vec3& lo, const Vec3& hi) {
    return (p.array() > lo.array()).all() && (p.array() < hi.array()).all();
  };
  std::size_t probes = 0;
  const BandCheck check = floorInBand([](const Vec3& x) { return 2.0 - x.x(); },
                                      [&](const Vec3& p) {
                                        ++probes;
                                        return insideBox(p, Vec3(0, 0, -0.2), Vec3(2, 1, 0)) ||
                                               insideBox(p, Vec3(2, 0, -0.2), Vec3(2.2, 1, 1));
                                      });
  EXPECT_GT(probes, 0u);
  EXPECT_LE(check.worst, 3e-5);
  // Two columns of 40 points, 0.0125 m and 0.0375 m from the wall, lie in the band.
  EXPECT_EQ(check.inBand, 2u * 40);
  EXPECT_EQ(check.stats.pointsGathered, check.inBand);
}

TEST(IndirectField, PointsOnNoElementOrUnevenAtTheDepthLimitAreGatheredExactly) {
  // A light with a kink across the floor: no quadratic fits it, so the triangles the kink crosses
  // stay uneven down to the depth limit, and their points are gathered; off the mesh too.
  Counted light{[](const SamplePoint& p) {
    return Eigen::Vector3d::Constant(100.0 + 40.0 * std::abs(p.position.x() - 0.61));
  }};
  const SurfaceMesh mesh = twoFaces();
  FieldOptions options;
  options.maxDepth = 2;
  options.boundaryBand = 0.0;
  IndirectField field(mesh, 3.0, light.gather(), options);
  std::vector<FacePoint> points = floorPoints(50);
  points.push_back(FacePoint{Vec3(2.5, 0.5, 0.0), 0, 0});  // beyond the floor's elements
  points.push_back(FacePoint{Vec3(1.0, 0.5, 0.0), 3, 0});  // a face without elements
  std::vector<float> channels(points.size() * 3);
  field.evaluate(points, channels);
  double worst = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double truth = light.light(SamplePoint{points[i].position, Vec3::UnitZ(), 0})[0];
    worst = std::max(worst, std::abs(channels[i * 3] - truth) / truth);
  }
  EXPECT_LE(worst, options.tolerance);
  // The kink's column of depth-2 triangles (0.125 m) holds about 6 points per row of 100.
  EXPECT_GE(field.stats().pointsGathered, 2u + 50u * 3u);
  EXPECT_LE(field.stats().pointsGathered, 2u + 50u * 20u);
}

}  // namespace
}  // namespace penumbra
