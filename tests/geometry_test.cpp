// Host geometry: every expected value here is computed another way than the code under test
// (closed forms, symmetry, brute force, complementary clips).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "geometry/convex_polygon.hpp"
#include "geometry/convex_polyhedron.hpp"
#include "geometry/exact_predicates.hpp"
#include "geometry/morton_order.hpp"
#include "geometry/nishita.hpp"

namespace penumbra {
namespace {

constexpr double kTol = 1e-9;

ConvexPolygon unitSquare() {
  return ConvexPolygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
}

ConvexPolyhedron unitCube() {
  return ConvexPolyhedron::box(Vec3::Zero(), Vec3::Ones());
}

std::vector<Vec3> randomPoints(int count, unsigned seed, double scale = 1.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-scale, scale);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) points.emplace_back(u(rng), u(rng), u(rng));
  return points;
}

std::vector<Vec3> randomSpherePoints(int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) points.push_back(Vec3(n(rng), n(rng), n(rng)).normalized());
  return points;
}

// Whether `to` follows `from` in a vertex loop.
bool loopRuns(const std::vector<int>& loop, int from, int to) {
  for (size_t i = 0; i < loop.size(); ++i) {
    if (loop[i] == from && loop[(i + 1) % loop.size()] == to) return true;
  }
  return false;
}

// The representation invariants promised by convex_polyhedron.hpp, checked from scratch.
// `merged`: no two adjacent faces coplanar, which holds for points that are either on a plane
// or clearly off it; points scattered by about the tolerance may leave nearly coplanar faces.
void expectWellFormed(const ConvexPolyhedron& p, double tol, bool merged = true) {
  ASSERT_FALSE(p.empty());
  const int v = static_cast<int>(p.vertices().size());
  const int e = static_cast<int>(p.edges().size());
  const int f = static_cast<int>(p.faces().size());
  EXPECT_EQ(v - e + f, 2) << "Euler characteristic of a sphere";

  for (const auto& edge : p.edges()) {
    EXPECT_TRUE(loopRuns(p.faces()[edge.left].vertices, edge.from, edge.to));
    EXPECT_TRUE(loopRuns(p.faces()[edge.right].vertices, edge.to, edge.from));
    EXPECT_NE(edge.left, edge.right);
  }
  int loopEdges = 0;
  for (const auto& face : p.faces()) loopEdges += static_cast<int>(face.vertices.size());
  EXPECT_EQ(loopEdges, 2 * e) << "every edge on exactly two loops";

  for (int i = 0; i < f; ++i) {
    const auto& face = p.faces()[i];
    const ConvexPolygon polygon = p.facePolygon(i);
    EXPECT_NEAR(face.plane.normal.norm(), 1.0, 1e-12);
    EXPECT_GT(polygon.normal().dot(face.plane.normal), merged ? 1.0 - 1e-9 : 0.0)
        << "loop counter-clockwise about the outward normal";
    for (int k : face.vertices) EXPECT_GE(face.plane.signedDistance(p.vertices()[k]), -tol * 10);
    EXPECT_TRUE(polygon.isPlanar(tol * 10));
    EXPECT_TRUE(polygon.isConvex(tol * 10));
    for (const Vec3& x : p.vertices()) EXPECT_LE(face.plane.signedDistance(x), tol * 10);
    EXPECT_LT(face.plane.signedDistance(p.centroid()), 0.0);
  }
  // Coplanar facets are merged: across every edge the other face has a vertex off this plane.
  for (const auto& edge : p.edges()) {
    if (!merged) break;
    const Plane& plane = p.faces()[edge.left].plane;
    double farthest = 0.0;
    for (int k : p.faces()[edge.right].vertices) {
      farthest = std::max(farthest, std::abs(plane.signedDistance(p.vertices()[k])));
    }
    EXPECT_GT(farthest, tol);
  }
  for (int i = 0; i < v; ++i) {
    for (int j = i + 1; j < v; ++j) EXPECT_GT((p.vertices()[i] - p.vertices()[j]).norm(), tol);
  }
}

// Brute force: the distinct planes through three points with every point on one side.
int bruteForceFacetCount(const std::vector<Vec3>& points) {
  std::vector<Plane> planes;
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) {
        Vec3 normal = (points[j] - points[i]).cross(points[k] - points[i]);
        if (normal.norm() < 1e-12) continue;
        Plane plane = Plane::through(points[i], normal);
        bool below = true, above = true;
        for (const Vec3& p : points) {
          below = below && plane.signedDistance(p) <= 1e-12;
          above = above && plane.signedDistance(p) >= -1e-12;
        }
        if (!below && !above) continue;
        if (above) plane = plane.flipped();
        const bool seen = std::ranges::any_of(planes, [&](const Plane& q) {
          return q.normal.dot(plane.normal) > 1 - 1e-9 && std::abs(q.offset - plane.offset) < 1e-9;
        });
        if (!seen) planes.push_back(plane);
      }
    }
  }
  return static_cast<int>(planes.size());
}

double signedAreaXY(const std::vector<Vec3>& loop) {
  double twice = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec3& a = loop[i];
    const Vec3& b = loop[(i + 1) % loop.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

// The silhouette's defining property: the cone from the viewpoint over each contour edge is a
// supporting plane of the polyhedron, with the polyhedron on its left when the loop runs
// counter-clockwise as seen from the viewpoint.
void expectSilhouetteSupports(const ConvexPolyhedron& p, const Vec3& eye,
                              const std::vector<Vec3>& loop) {
  ASSERT_GE(loop.size(), 3u);
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec3 normal = (loop[i] - eye).cross(loop[(i + 1) % loop.size()] - eye).normalized();
    for (const Vec3& x : p.vertices()) EXPECT_LE(normal.dot(x - eye), 1e-9);
  }
  const Vec3 loopNormal = ConvexPolygon(loop).normal();
  EXPECT_GT(loopNormal.dot(eye - ConvexPolygon(loop).centroid()), 0.0) << "CCW seen from eye";
}

// ---------------------------------------------------------------------------------------------
// Exact orientation

TEST(ExactPredicates, OrientationOfATetrahedron) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_EQ(orientationSign(a, b, c, Vec3(0.2, 0.2, 1)), 1) << "the side (b-a)x(c-a) points to";
  EXPECT_EQ(orientationSign(a, b, c, Vec3(0.2, 0.2, -1)), -1);
  EXPECT_EQ(orientationSign(a, c, b, Vec3(0.2, 0.2, 1)), -1);
  EXPECT_EQ(orientationSign(a, b, c, Vec3(5, -7, 0)), 0);
}

TEST(ExactPredicates, CoplanarLargeIntegersAreExactlyZero) {
  // Points (x, y, x + y) with x, y near 2^26 lie exactly on a plane and are exactly
  // representable, but the determinant's products reach 2^78: a plain double evaluation
  // rounds. One ulp off the plane must give a sign.
  std::mt19937_64 rng(13);
  std::uniform_int_distribution<int64_t> coordinate(1 << 25, 1 << 26);
  auto onPlane = [&] {
    const double x = static_cast<double>(coordinate(rng)), y = static_cast<double>(coordinate(rng));
    return Vec3(x, y, x + y);
  };
  int naiveNonZero = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Vec3 a = onPlane(), b = onPlane(), c = onPlane(), p = onPlane();
    EXPECT_EQ(orientationSign(a, b, c, p), 0);
    naiveNonZero += (b - a).cross(c - a).dot(p - a) != 0.0;
    const Vec3 above(p.x(), p.y(), std::nextafter(p.z(), INFINITY));
    const Vec3 below(p.x(), p.y(), std::nextafter(p.z(), -INFINITY));
    const int up = orientationSign(a, b, c, above);
    EXPECT_NE(up, 0);
    EXPECT_EQ(orientationSign(a, b, c, below), -up);
    // Which way is up: the sign of the normal's z (the plane z = x + y is not vertical).
    EXPECT_EQ(up, (b - a).cross(c - a).z() > 0 ? 1 : -1);
  }
  EXPECT_GT(naiveNonZero, 0) << "the test would not tell an exact predicate from a naive one";
}

// ---------------------------------------------------------------------------------------------
// ConvexPolygon

TEST(ConvexPolygon, UnitSquareMeasures) {
  const ConvexPolygon square = unitSquare();
  EXPECT_TRUE(square.normal().isApprox(Vec3::UnitZ()));
  EXPECT_DOUBLE_EQ(square.area(), 1.0);
  EXPECT_TRUE(square.centroid().isApprox(Vec3(0.5, 0.5, 0.0)));
  EXPECT_NEAR(square.plane().offset, 0.0, 1e-15);
  EXPECT_TRUE(square.reversed().normal().isApprox(-Vec3::UnitZ()));
  EXPECT_DOUBLE_EQ(square.reversed().area(), 1.0);
}

TEST(ConvexPolygon, TiltedTriangleMatchesCrossProduct) {
  const Vec3 a(1, 2, 3), b(4, -1, 2), c(0, 5, -2);
  const ConvexPolygon triangle({a, b, c});
  const Vec3 cross = (b - a).cross(c - a);
  EXPECT_NEAR(triangle.area(), 0.5 * cross.norm(), 1e-12);
  EXPECT_TRUE(triangle.normal().isApprox(cross.normalized(), 1e-12));
  EXPECT_TRUE(triangle.centroid().isApprox((a + b + c) / 3.0, 1e-12));
  EXPECT_NEAR(triangle.plane().signedDistance(a), 0.0, 1e-12);
  EXPECT_NEAR(triangle.plane().signedDistance(a + cross.normalized()), 1.0, 1e-12);
}

TEST(ConvexPolygon, TrapezoidCentroidClosedForm) {
  // Bases 4 (y = 0) and 2 (y = 3): centroid height h (a + 2b) / (3 (a + b)) = 3 * 8 / 18.
  const ConvexPolygon trapezoid({{0, 0, 1}, {4, 0, 1}, {3, 3, 1}, {1, 3, 1}});
  EXPECT_DOUBLE_EQ(trapezoid.area(), 9.0);
  EXPECT_TRUE(trapezoid.centroid().isApprox(Vec3(2.0, 3.0 * 8.0 / 18.0, 1.0), 1e-12));
}

TEST(ConvexPolygon, PlanarityCheck) {
  const Vec3 u = Vec3(1, 1, 0).normalized(), w = Vec3(0, 0.3, 1).normalized();
  EXPECT_TRUE(ConvexPolygon({Vec3::Zero(), u, u + w, w}).isPlanar(1e-9));
  EXPECT_FALSE(ConvexPolygon({Vec3::Zero(), u, u + w + Vec3(0, 0, 1e-3), w}).isPlanar(1e-6));
  EXPECT_TRUE(ConvexPolygon({Vec3::Zero(), u, u + w + Vec3(0, 0, 1e-9), w}).isPlanar(1e-6));
  EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {1, 0, 0}}).isPlanar(1e-6));
  EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}).isPlanar(1e-6)) << "no area";
}

TEST(ConvexPolygon, ConvexityCheck) {
  std::vector<Vec3> hexagon;
  for (int k = 0; k < 6; ++k) {
    const double a = k * std::numbers::pi / 3.0;
    hexagon.emplace_back(std::cos(a), std::sin(a), 2.0);
  }
  EXPECT_TRUE(ConvexPolygon(hexagon).isConvex(1e-9));
  EXPECT_TRUE(ConvexPolygon(hexagon).reversed().isConvex(1e-9)) << "either orientation";
  EXPECT_TRUE(
      ConvexPolygon({{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}).isConvex(1e-9))
      << "collinear consecutive vertices are allowed";
  EXPECT_FALSE(
      ConvexPolygon({{0, 0, 0}, {2, 0, 0}, {1, 0.5, 0}, {2, 2, 0}, {0, 2, 0}}).isConvex(1e-9))
      << "reflex vertex";
  std::vector<Vec3> pentagram;
  for (int k = 0; k < 5; ++k) {
    const double a = k * 4.0 * std::numbers::pi / 5.0;
    pentagram.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  EXPECT_FALSE(ConvexPolygon(pentagram).isConvex(1e-9)) << "winds twice, turns left everywhere";
  EXPECT_FALSE(ConvexPolygon({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}).isConvex(1e-9)) << "no area";
  // A reflex dent smaller than the tolerance is accepted.
  EXPECT_TRUE(
      ConvexPolygon({{0, 0, 0}, {1, 1e-10, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}).isConvex(1e-9));
}

TEST(ConvexPolygon, ClipAreas) {
  const ConvexPolygon square = unitSquare();
  const ConvexPolygon left = square.clipped(Plane{Vec3::UnitX(), 0.3}, kTol);
  EXPECT_NEAR(left.area(), 0.3, 1e-12);
  EXPECT_TRUE(left.centroid().isApprox(Vec3(0.15, 0.5, 0), 1e-12));
  EXPECT_TRUE(left.normal().isApprox(Vec3::UnitZ())) << "orientation kept";

  const ConvexPolygon diagonal = square.clipped(Plane::through({1, 0, 0}, {1, 1, 0}), kTol);
  EXPECT_EQ(diagonal.size(), 3) << "the diagonal runs through two corners: no new vertices";
  EXPECT_NEAR(diagonal.area(), 0.5, 1e-12);

  // x + y <= 0.5 cuts a corner triangle of legs 0.5.
  const ConvexPolygon corner = square.clipped(Plane::through({0.25, 0.25, 0}, {1, 1, 0}), kTol);
  EXPECT_NEAR(corner.area(), 0.125, 1e-12);
  EXPECT_EQ(corner.size(), 3);

  const ConvexPolygon whole = square.clipped(Plane{Vec3::UnitX(), 1.0}, kTol);
  EXPECT_EQ(whole.vertices(), square.vertices());
  EXPECT_TRUE(square.clipped(Plane{-Vec3::UnitX(), -1.0}, kTol).empty()) << "touches only";
  EXPECT_TRUE(square.clipped(Plane::through({0, 0, 0}, {1, 1, 0}), kTol).empty()) << "a corner";
  EXPECT_TRUE(square.clipped(Plane{Vec3::UnitX(), -0.5}, kTol).empty());
  // A plane containing the polygon keeps it whole.
  EXPECT_DOUBLE_EQ(square.clipped(Plane{Vec3::UnitZ(), 0.0}, kTol).area(), 1.0);
}

TEST(ConvexPolygon, ComplementaryClipsAddUp) {
  std::vector<Vec3> octagon;
  for (int k = 0; k < 8; ++k) {
    const double a = k * std::numbers::pi / 4.0;
    octagon.emplace_back(3 * std::cos(a), 0.5, 3 * std::sin(a));
  }
  const ConvexPolygon polygon(octagon);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 50; ++trial) {
    const Plane plane = Plane::through(Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)));
    const double a = polygon.clipped(plane, kTol).area();
    const double b = polygon.clipped(plane.flipped(), kTol).area();
    EXPECT_NEAR(a + b, polygon.area(), 1e-9);
  }
}

// ---------------------------------------------------------------------------------------------
// ConvexPolyhedron: box and prism

TEST(ConvexPolyhedron, BoxClosedForms) {
  const Vec3 lo(-1, 2, 0.5), hi(2, 2.5, 4.5);  // 3 x 0.5 x 4
  const ConvexPolyhedron box = ConvexPolyhedron::box(lo, hi);
  EXPECT_EQ(box.vertices().size(), 8u);
  EXPECT_EQ(box.edges().size(), 12u);
  EXPECT_EQ(box.faces().size(), 6u);
  EXPECT_NEAR(box.volume(), 6.0, 1e-12);
  EXPECT_NEAR(box.surfaceArea(), 2 * (3 * 0.5 + 3 * 4 + 0.5 * 4), 1e-12);
  EXPECT_TRUE(box.centroid().isApprox((lo + hi) / 2, 1e-12));
  for (const auto& face : box.faces()) EXPECT_EQ(face.vertices.size(), 4u);
  expectWellFormed(box, kTol);
  EXPECT_TRUE(ConvexPolyhedron::box(lo, Vec3(2, 2, 4.5)).empty()) << "no thickness";
}

TEST(ConvexPolyhedron, PrismOverTriangleEitherSide) {
  const ConvexPolygon triangle({{0, 0, 0}, {2, 0, 0}, {0, 1, 0}});  // area 1, normal +z
  for (const Vec3& extrusion : {Vec3(0, 0, 3), Vec3(0, 0, -3), Vec3(1, 0.5, 3)}) {
    const ConvexPolyhedron prism = ConvexPolyhedron::prism(triangle, extrusion, kTol);
    EXPECT_EQ(prism.vertices().size(), 6u);
    EXPECT_EQ(prism.faces().size(), 5u);
    EXPECT_EQ(prism.edges().size(), 9u);
    EXPECT_NEAR(prism.volume(), 1.0 * 3.0, 1e-12) << "area times height";
    EXPECT_TRUE(prism.centroid().isApprox(Vec3(2.0 / 3, 1.0 / 3, 0) + extrusion / 2, 1e-12));
    expectWellFormed(prism, kTol);
  }
  EXPECT_TRUE(ConvexPolyhedron::prism(triangle, Vec3(1, 1, 0), kTol).empty()) << "in its plane";
  EXPECT_TRUE(ConvexPolyhedron::prism(ConvexPolygon(), Vec3(0, 0, 1), kTol).empty());
}

TEST(ConvexPolyhedron, PrismMergesSidesOfCollinearBaseVertices) {
  // A unit square with a vertex in the middle of one side: the prism is still a box.
  const ConvexPolygon base({{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
  const ConvexPolyhedron prism = ConvexPolyhedron::prism(base, Vec3(0, 0, 2), kTol);
  EXPECT_EQ(prism.faces().size(), 6u);
  EXPECT_EQ(prism.vertices().size(), 8u);
  EXPECT_NEAR(prism.volume(), 2.0, 1e-12);
  expectWellFormed(prism, kTol);
}

TEST(ConvexPolyhedron, CylinderPrismVolumeAndArea) {
  const int n = 64;
  const double r = 0.7, h = 2.5;
  std::vector<Vec3> ring;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    ring.emplace_back(r * std::cos(a), r * std::sin(a), 1.0);
  }
  const ConvexPolyhedron cylinder = ConvexPolyhedron::prism(ConvexPolygon(ring), {0, 0, h}, kTol);
  const double baseArea = 0.5 * n * r * r * std::sin(2 * std::numbers::pi / n);
  const double side = 2 * r * std::sin(std::numbers::pi / n);
  EXPECT_EQ(cylinder.faces().size(), static_cast<size_t>(n + 2));
  EXPECT_NEAR(cylinder.volume(), baseArea * h, 1e-12);
  EXPECT_NEAR(cylinder.surfaceArea(), 2 * baseArea + n * side * h, 1e-11);
  expectWellFormed(cylinder, kTol);
}

// ---------------------------------------------------------------------------------------------
// ConvexPolyhedron::hull

TEST(ConvexHull, CubeCornersWithInteriorAndSurfacePointsGiveSixQuads) {
  std::vector<Vec3> points = randomPoints(200, 1, 0.5);
  for (Vec3& p : points) p += Vec3::Constant(0.5);  // interior of [0,1]^3
  for (int i = 0; i < 8; ++i) points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  // Points on faces and edges, and near-duplicates of corners: all must disappear.
  points.emplace_back(0.5, 0.5, 1.0);
  points.emplace_back(0.0, 0.3, 0.7);
  points.emplace_back(0.5, 0.0, 0.0);
  points.emplace_back(1.0, 1.0, 0.25);
  points.emplace_back(1.0 - 1e-11, 1.0, 1.0 + 1e-11);
  points.emplace_back(1e-12, -1e-12, 0.0);
  std::ranges::shuffle(points, std::mt19937(3));
  const ConvexPolyhedron cube = ConvexPolyhedron::hull(points, kTol);
  EXPECT_EQ(cube.vertices().size(), 8u);
  EXPECT_EQ(cube.edges().size(), 12u);
  EXPECT_EQ(cube.faces().size(), 6u);
  for (const auto& face : cube.faces()) EXPECT_EQ(face.vertices.size(), 4u);
  EXPECT_NEAR(cube.volume(), 1.0, 1e-9);
  EXPECT_NEAR(cube.surfaceArea(), 6.0, 1e-9);
  EXPECT_TRUE(cube.centroid().isApprox(Vec3::Constant(0.5), 1e-9));
  expectWellFormed(cube, kTol);
}

TEST(ConvexHull, EdgePointsBeforeCornersAreRemoved) {
  // A long box whose edge points are farther from the centre than the corners of the short
  // end: a point on an edge can join the hull before the corners that make it redundant.
  std::vector<Vec3> points;
  for (int i = 0; i < 8; ++i) points.emplace_back(10.0 * (i & 1), (i >> 1) & 1, (i >> 2) & 1);
  for (double x = 0.5; x < 10; x += 0.75) {
    points.emplace_back(x, 0, 0);
    points.emplace_back(x, 1, 1);
    points.emplace_back(x, 0.5, 1);
  }
  std::ranges::reverse(points);
  const ConvexPolyhedron box = ConvexPolyhedron::hull(points, kTol);
  EXPECT_EQ(box.vertices().size(), 8u);
  EXPECT_EQ(box.faces().size(), 6u);
  EXPECT_NEAR(box.volume(), 10.0, 1e-9);
  expectWellFormed(box, kTol);
}

TEST(ConvexHull, RandomPointsContainedAndVerticesAreInputPoints) {
  for (unsigned seed = 0; seed < 20; ++seed) {
    const std::vector<Vec3> points = randomPoints(20 + 10 * seed, seed, 3.0);
    const ConvexPolyhedron hull = ConvexPolyhedron::hull(points, kTol);
    expectWellFormed(hull, kTol);
    for (const Vec3& p : points) {
      for (const auto& face : hull.faces()) EXPECT_LE(face.plane.signedDistance(p), 1e-9);
    }
    for (const Vec3& v : hull.vertices()) {
      EXPECT_TRUE(std::ranges::find(points, v) != points.end()) << "vertex not an input point";
    }
    // Random points are in general position: all faces are triangles, one per supporting
    // plane found by brute force.
    if (points.size() <= 60) {
      EXPECT_EQ(static_cast<int>(hull.faces().size()), bruteForceFacetCount(points));
    }
  }
}

TEST(ConvexHull, PointsOnASphereAreAllVertices) {
  const std::vector<Vec3> points = randomSpherePoints(500, 11);
  const ConvexPolyhedron hull = ConvexPolyhedron::hull(points, kTol);
  expectWellFormed(hull, kTol);
  EXPECT_EQ(hull.vertices().size(), points.size());
  EXPECT_EQ(hull.faces().size(), 2 * points.size() - 4) << "triangulated sphere: F = 2V - 4";
  EXPECT_LT(hull.volume(), 4.0 / 3.0 * std::numbers::pi);
  EXPECT_GT(hull.volume(), 0.95 * 4.0 / 3.0 * std::numbers::pi);
  EXPECT_LT(hull.centroid().norm(), 0.02);
}

TEST(ConvexHull, RegularPolytopesWithCoplanarFacets) {
  // Octahedron: 8 triangles; cuboctahedron: 8 triangles + 6 squares (from 12 edge midpoints).
  const ConvexPolyhedron octahedron = ConvexPolyhedron::hull(
      {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}, kTol);
  EXPECT_EQ(octahedron.faces().size(), 8u);
  EXPECT_NEAR(octahedron.volume(), 4.0 / 3.0, 1e-12);
  expectWellFormed(octahedron, kTol);

  std::vector<Vec3> midpoints;
  for (int axis = 0; axis < 3; ++axis) {
    for (int s = 0; s < 4; ++s) {
      Vec3 p = Vec3::Zero();
      p[(axis + 1) % 3] = (s & 1) ? 1 : -1;
      p[(axis + 2) % 3] = (s & 2) ? 1 : -1;
      midpoints.push_back(p);
    }
  }
  const ConvexPolyhedron cuboctahedron = ConvexPolyhedron::hull(midpoints, kTol);
  EXPECT_EQ(cuboctahedron.faces().size(), 14u);
  EXPECT_EQ(cuboctahedron.edges().size(), 24u);
  int squares = 0;
  for (const auto& face : cuboctahedron.faces()) squares += face.vertices.size() == 4;
  EXPECT_EQ(squares, 6);
  EXPECT_NEAR(cuboctahedron.volume(), 8.0 - 8.0 / 6.0, 1e-12) << "cube minus 8 corner tetrahedra";
  expectWellFormed(cuboctahedron, kTol);
}

TEST(ConvexHull, LatticeBallsWithManyCoplanarPoints) {
  // Integer points in a ball: many points on each facet and on each edge, and facets meeting
  // at shallow angles. Rotated and moved away from the origin, no coordinate is exact any more,
  // yet the hull must be the same polyhedron: same counts, same volume.
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()) * Eigen::AngleAxisd(1.1, Vec3::UnitX()))
          .toRotationMatrix();
  const Vec3 shift(100, -50, 20);
  const double tol = 1e-7;
  for (const int radius : {2, 3, 5}) {
    std::vector<Vec3> points, moved;
    for (int x = -radius; x <= radius; ++x) {
      for (int y = -radius; y <= radius; ++y) {
        for (int z = -radius; z <= radius; ++z) {
          if (x * x + y * y + z * z > radius * radius) continue;
          points.emplace_back(x, y, z);
          moved.push_back(rotation * points.back() + shift);
        }
      }
    }
    const ConvexPolyhedron hull = ConvexPolyhedron::hull(points, tol);
    const ConvexPolyhedron movedHull = ConvexPolyhedron::hull(moved, tol);
    expectWellFormed(hull, tol);
    expectWellFormed(movedHull, tol);
    EXPECT_EQ(movedHull.vertices().size(), hull.vertices().size());
    EXPECT_EQ(movedHull.faces().size(), hull.faces().size());
    EXPECT_NEAR(movedHull.volume(), hull.volume(), 1e-9 * hull.volume());
    EXPECT_TRUE(movedHull.centroid().isApprox(rotation * hull.centroid() + shift, 1e-12));
    for (const Vec3& p : moved) {
      for (const auto& face : movedHull.faces()) {
        EXPECT_LE(face.plane.signedDistance(p), 10 * tol);
      }
    }
  }
}

TEST(ConvexHull, CubeLatticeIsSixQuads) {
  std::vector<Vec3> points;
  for (int x = 0; x <= 4; ++x) {
    for (int y = 0; y <= 4; ++y) {
      for (int z = 0; z <= 4; ++z) points.emplace_back(0.25 * x, 0.25 * y, 0.25 * z);
    }
  }
  std::ranges::shuffle(points, std::mt19937(5));
  const ConvexPolyhedron cube = ConvexPolyhedron::hull(points, kTol);
  EXPECT_EQ(cube.vertices().size(), 8u);
  EXPECT_EQ(cube.faces().size(), 6u);
  EXPECT_NEAR(cube.volume(), 1.0, 1e-12);
  expectWellFormed(cube, kTol);
}

TEST(ConvexHull, PointsScatteredByTheToleranceStayValid) {
  // The hard case for a hull with a tolerance: points that are coplanar only up to about the
  // tolerance (on the faces of a cube, on a lattice), where every merge decision is borderline.
  // A quickhull deciding "outside" with the tolerance lost points here by the size of the cube.
  std::mt19937 rng(31);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 60; ++trial) {
    const double tol = std::pow(10.0, -3 - trial % 7);
    std::vector<Vec3> points;
    for (int i = 0; i < 40 + 5 * trial; ++i) {
      Vec3 p(u(rng), u(rng), u(rng));
      if (trial % 2 == 0) {
        p[i % 3] = p[i % 3] > 0 ? 1 : -1;  // on a face of [-1,1]^3
      } else {
        p = (3 * p).array().round();  // on the lattice
      }
      points.push_back(p + tol * Vec3(u(rng), u(rng), u(rng)));
    }
    const ConvexPolyhedron hull = ConvexPolyhedron::hull(points, tol);
    expectWellFormed(hull, tol, /*merged=*/false);
    for (const Vec3& p : points) {
      for (const auto& face : hull.faces()) EXPECT_LE(face.plane.signedDistance(p), 10 * tol);
    }
    for (const Vec3& v : hull.vertices()) EXPECT_TRUE(std::ranges::find(points, v) != points.end());
  }
}

TEST(ConvexHull, DegenerateInputsGiveEmpty) {
  EXPECT_TRUE(ConvexPolyhedron::hull({}, kTol).empty());
  EXPECT_TRUE(ConvexPolyhedron::hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, kTol).empty());
  EXPECT_TRUE(ConvexPolyhedron::hull(std::vector<Vec3>(10, Vec3(1, 2, 3)), kTol).empty());
  std::vector<Vec3> collinear, coplanar, thin;
  for (const Vec3& p : randomPoints(50, 5)) {
    collinear.push_back(Vec3(1, 2, 3) * p.x());
    coplanar.push_back(Vec3(p.x(), p.y(), 0.3 * p.x() - 0.2 * p.y() + 1));
    thin.push_back(Vec3(p.x(), p.y(), 0.4 * kTol * p.z()));
  }
  EXPECT_TRUE(ConvexPolyhedron::hull(collinear, kTol).empty());
  EXPECT_TRUE(ConvexPolyhedron::hull(coplanar, kTol).empty());
  EXPECT_TRUE(ConvexPolyhedron::hull(thin, kTol).empty()) << "thinner than the tolerance";
}

// ---------------------------------------------------------------------------------------------
// ConvexPolyhedron::clipped

TEST(ConvexPolyhedronClip, UnitCubeByAxisPlane) {
  const ConvexPolyhedron part = unitCube().clipped(Plane{Vec3::UnitX(), 0.3}, kTol);
  EXPECT_NEAR(part.volume(), 0.3, 1e-12);
  EXPECT_EQ(part.faces().size(), 6u);
  EXPECT_TRUE(part.centroid().isApprox(Vec3(0.15, 0.5, 0.5), 1e-12));
  expectWellFormed(part, kTol);
}

TEST(ConvexPolyhedronClip, UnitCubeByDiagonalPlanes) {
  // x + y <= 1: a triangular prism, half the cube.
  const ConvexPolyhedron wedge = unitCube().clipped(Plane::through({1, 0, 0}, {1, 1, 0}), kTol);
  EXPECT_NEAR(wedge.volume(), 0.5, 1e-12);
  EXPECT_EQ(wedge.faces().size(), 5u);
  EXPECT_EQ(wedge.vertices().size(), 6u);
  expectWellFormed(wedge, kTol);

  // x + y + z <= 1.5 through the centre: half by symmetry, cut by a regular hexagon.
  const ConvexPolyhedron half =
      unitCube().clipped(Plane::through(Vec3::Constant(0.5), Vec3::Ones()), kTol);
  EXPECT_NEAR(half.volume(), 0.5, 1e-12);
  EXPECT_EQ(half.faces().size(), 7u);
  const int cap = half.faceContaining(Vec3::Constant(0.5), Vec3::Ones(), kTol);
  ASSERT_GE(cap, 0);
  EXPECT_EQ(half.faces()[cap].vertices.size(), 6u);
  EXPECT_NEAR(half.facePolygon(cap).area(), 3.0 * std::sqrt(3.0) / 4.0, 1e-12)
      << "regular hexagon of side sqrt(2)/2";
  expectWellFormed(half, kTol);
}

TEST(ConvexPolyhedronClip, FastPathsAndSlivers) {
  const ConvexPolyhedron cube = unitCube();
  const ConvexPolyhedron same = cube.clipped(Plane{Vec3::UnitX(), 1.0}, kTol);
  EXPECT_EQ(same.vertices(), cube.vertices());
  EXPECT_EQ(same.faces().size(), cube.faces().size());
  EXPECT_TRUE(cube.clipped(Plane{Vec3::UnitX(), 0.0}, kTol).empty()) << "touches a face";
  EXPECT_TRUE(cube.clipped(Plane{Vec3::UnitX(), -1.0}, kTol).empty());
  EXPECT_TRUE(cube.clipped(Plane{Vec3::UnitX(), 0.5 * kTol}, kTol).empty()) << "thinner than tol";
  EXPECT_TRUE(ConvexPolyhedron().clipped(Plane{}, kTol).empty());
}

TEST(ConvexPolyhedronClip, ComplementaryClipsAddUp) {
  const ConvexPolyhedron hull = ConvexPolyhedron::hull(randomPoints(60, 42, 2.0), kTol);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 40; ++trial) {
    const Plane plane = Plane::through(Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)));
    const ConvexPolyhedron a = hull.clipped(plane, kTol);
    const ConvexPolyhedron b = hull.clipped(plane.flipped(), kTol);
    EXPECT_NEAR(a.volume() + b.volume(), hull.volume(), 1e-9);
    if (!a.empty()) expectWellFormed(a, kTol);
    if (!b.empty()) expectWellFormed(b, kTol);
    // The cap of each side is the same polygon.
    for (const Vec3& v : a.vertices()) EXPECT_LE(plane.signedDistance(v), kTol);
  }
}

TEST(ConvexPolyhedronClip, RepeatedClipsToAnOctahedron) {
  // Clipping [-1,1]^3 by the 8 planes |x|+|y|+|z| <= 1 leaves the octahedron (volume 4/3).
  ConvexPolyhedron p = ConvexPolyhedron::box(-Vec3::Ones(), Vec3::Ones());
  for (int s = 0; s < 8; ++s) {
    const Vec3 n((s & 1) ? 1 : -1, (s & 2) ? 1 : -1, (s & 4) ? 1 : -1);
    p = p.clipped(Plane::through(Vec3(n.x(), 0, 0), n), kTol);
  }
  EXPECT_NEAR(p.volume(), 4.0 / 3.0, 1e-12);
  EXPECT_EQ(p.faces().size(), 8u);
  EXPECT_EQ(p.vertices().size(), 6u);
  expectWellFormed(p, kTol);
}

TEST(ConvexPolyhedronClip, RepeatedRandomClipsOfAFarAwayCylinder) {
  // Scene-sized coordinates (a room 1 km from the origin) with the scene's tolerance.
  const Vec3 origin(1000, -700, 3);
  const double tol = Tolerance::forSceneSize(2000).length;
  std::vector<Vec3> ring;
  for (int k = 0; k < 48; ++k) {
    const double a = 2 * std::numbers::pi * k / 48;
    ring.push_back(origin + Vec3(0.4 * std::cos(a), 0.4 * std::sin(a), 0));
  }
  ConvexPolyhedron p = ConvexPolyhedron::prism(ConvexPolygon(ring), {0, 0, 2.7}, tol);
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int step = 0; step < 30 && !p.empty(); ++step) {
    const Vec3 through = p.centroid() + 0.2 * Vec3(u(rng), u(rng), u(rng));
    const Plane plane = Plane::through(through, Vec3(u(rng), u(rng), u(rng)));
    const ConvexPolyhedron kept = p.clipped(plane, tol);
    const ConvexPolyhedron rest = p.clipped(plane.flipped(), tol);
    EXPECT_NEAR(kept.volume() + rest.volume(), p.volume(), 1e-9 * p.volume() + 1e-9);
    p = kept;
    if (!p.empty()) expectWellFormed(p, tol);
  }
}

// ---------------------------------------------------------------------------------------------
// Point queries

TEST(ConvexPolyhedron, ContainsStrictly) {
  const ConvexPolyhedron cube = unitCube();
  EXPECT_TRUE(cube.containsStrictly(Vec3::Constant(0.5), kTol));
  EXPECT_FALSE(cube.containsStrictly(Vec3(0.5, 0.5, 1.0), kTol)) << "on a face";
  EXPECT_FALSE(cube.containsStrictly(Vec3(0.5, 0.5, 1.0 - 0.5 * kTol), kTol));
  EXPECT_TRUE(cube.containsStrictly(Vec3(0.5, 0.5, 1.0 - 2 * kTol), kTol));
  EXPECT_FALSE(cube.containsStrictly(Vec3(2, 0.5, 0.5), kTol));
  EXPECT_FALSE(ConvexPolyhedron().containsStrictly(Vec3::Zero(), kTol));
}

TEST(ConvexPolyhedron, FaceContaining) {
  const ConvexPolyhedron cube = unitCube();
  const int top = cube.faceContaining(Vec3(0.3, 0.6, 1.0 + 0.5 * kTol), Vec3::UnitZ(), kTol);
  ASSERT_GE(top, 0);
  EXPECT_TRUE(cube.faces()[top].plane.normal.isApprox(Vec3::UnitZ()));
  // On the edge between top and +x: the hint picks.
  const Vec3 edgePoint(1.0, 0.5, 1.0);
  const int a = cube.faceContaining(edgePoint, Vec3(0.1, 0, 1), kTol);
  const int b = cube.faceContaining(edgePoint, Vec3(1, 0, 0.1), kTol);
  EXPECT_TRUE(cube.faces()[a].plane.normal.isApprox(Vec3::UnitZ()));
  EXPECT_TRUE(cube.faces()[b].plane.normal.isApprox(Vec3::UnitX()));
  EXPECT_EQ(cube.faceContaining(Vec3(1.5, 0.5, 1.0), Vec3::UnitZ(), kTol), -1)
      << "in the plane, off the face";
  EXPECT_EQ(cube.faceContaining(Vec3::Constant(0.5), Vec3::UnitZ(), kTol), -1) << "interior";
  EXPECT_EQ(cube.faceContaining(Vec3(0.5, 0.5, 1.1), Vec3::UnitZ(), kTol), -1) << "above";
}

// ---------------------------------------------------------------------------------------------
// Silhouette (Nishita's contour line)

TEST(Silhouette, BoxFromFarAlongZIsItsTopOutlineCounterClockwise) {
  const ConvexPolyhedron box = ConvexPolyhedron::box(Vec3(0, 0, 0), Vec3(2, 1, 3));
  const Vec3 eye(1.0, 0.5, 100.0);
  const std::vector<Vec3> loop = box.silhouette(eye);
  ASSERT_EQ(loop.size(), 4u);
  EXPECT_NEAR(signedAreaXY(loop), 2.0, 1e-12) << "counter-clockwise, the projected outline";
  for (const Vec3& v : loop) EXPECT_DOUBLE_EQ(v.z(), 3.0);
  expectSilhouetteSupports(box, eye, loop);
}

TEST(Silhouette, BoxFromCornerEdgeAndFaceDirections) {
  const ConvexPolyhedron cube = unitCube();
  const Vec3 corner(5, 6, 7), edge(5, 6, 0.5), face(0.2, 0.9, -4);
  EXPECT_EQ(cube.silhouette(corner).size(), 6u);
  EXPECT_EQ(cube.silhouette(edge).size(), 6u);
  EXPECT_EQ(cube.silhouette(face).size(), 4u);
  for (const Vec3& eye : {corner, edge, face})
    expectSilhouetteSupports(cube, eye, cube.silhouette(eye));
  // From far along the main diagonal the outline is a regular hexagon, counter-clockwise.
  const Vec3 diagonal = Vec3::Ones().normalized();
  const std::vector<Vec3> hexagon = cube.silhouette(Vec3::Constant(0.5) + 1e6 * diagonal);
  ASSERT_EQ(hexagon.size(), 6u);
  EXPECT_GT(ConvexPolygon(hexagon).normal().dot(diagonal), 0.0);
  for (const Vec3& v : hexagon) {
    const Vec3 radial =
        (v - Vec3::Constant(0.5)) - (v - Vec3::Constant(0.5)).dot(diagonal) * diagonal;
    EXPECT_NEAR(radial.norm(), std::sqrt(2.0 / 3.0), 1e-12);
  }
}

TEST(Silhouette, InsideOrOnBoundaryIsEmpty) {
  const ConvexPolyhedron cube = unitCube();
  EXPECT_TRUE(cube.silhouette(Vec3::Constant(0.5)).empty());
  EXPECT_TRUE(cube.silhouette(Vec3(0.5, 0.5, 1.0)).empty()) << "on a face";
  EXPECT_TRUE(cube.silhouette(Vec3(1.0, 0.5, 1.0)).empty()) << "on an edge";
  EXPECT_TRUE(cube.silhouette(Vec3(1.0, 1.0, 1.0)).empty()) << "at a vertex";
  EXPECT_TRUE(ConvexPolyhedron().silhouette(Vec3::Zero()).empty());
}

TEST(Silhouette, RandomHullsFromRandomViewpoints) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-10, 10);
  for (unsigned seed = 0; seed < 10; ++seed) {
    const ConvexPolyhedron hull = ConvexPolyhedron::hull(randomPoints(40, 100 + seed), kTol);
    for (int trial = 0; trial < 10; ++trial) {
      const Vec3 eye(u(rng), u(rng), u(rng));
      if (hull.containsStrictly(eye, 0.0)) continue;
      expectSilhouetteSupports(hull, eye, hull.silhouette(eye));
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Nishita's F and H

TEST(Nishita, FIsSignedDistanceFromTheFace) {
  const Plane face = Plane::through(Vec3(0, 0, 2), Vec3(0, 0, 5));
  EXPECT_DOUBLE_EQ(nishitaF(face, Vec3(7, -3, 5)), 3.0);
  EXPECT_DOUBLE_EQ(nishitaF(face, Vec3(0, 0, 0)), -2.0);
}

TEST(Nishita, HClassification) {
  const Plane ground{Vec3::UnitZ(), 0.0};
  const std::vector<Vec3> above{{0, 0, 1}, {1, 2, 3}}, below{{0, 0, -1}, {5, 5, -2}};
  const std::vector<Vec3> across{{0, 0, 1}, {0, 0, -1}}, inPlane{{0, 0, 0}, {1, 1, 0}};
  const std::vector<Vec3> touching{{0, 0, 0}, {1, 1, -1}}, nearlyIn{{0, 0, -0.5 * kTol}, {0, 1, 1}};
  EXPECT_EQ(nishitaH(ground, above, kTol), Side::Positive);
  EXPECT_EQ(nishitaH(ground, below, kTol), Side::Negative);
  EXPECT_EQ(nishitaH(ground, across, kTol), Side::Straddles);
  EXPECT_EQ(nishitaH(ground, inPlane, kTol), Side::Positive) << "a set in the plane";
  EXPECT_EQ(nishitaH(ground, touching, kTol), Side::Negative) << "closed half-spaces";
  EXPECT_EQ(nishitaH(ground, nearlyIn, kTol), Side::Positive) << "within tolerance is on";

  const ConvexPolyhedron cube = unitCube();
  EXPECT_EQ(nishitaH(Plane{Vec3::UnitZ(), 1.0}, cube, kTol), Side::Negative);
  EXPECT_EQ(nishitaH(Plane{-Vec3::UnitZ(), 0.0}, cube, kTol), Side::Negative);
  EXPECT_EQ(nishitaH(Plane{Vec3::UnitZ(), 0.0}, cube, kTol), Side::Positive);
  EXPECT_EQ(nishitaH(Plane{Vec3::UnitZ(), 0.5}, cube, kTol), Side::Straddles);

  const ConvexPolygon square = unitSquare();
  EXPECT_EQ(nishitaH(Plane{Vec3::UnitZ(), 0.0}, square, kTol), Side::Positive);
  EXPECT_EQ(nishitaH(Plane{Vec3::UnitX(), 1.0}, square, kTol), Side::Negative);
  EXPECT_EQ(nishitaH(Plane{Vec3::UnitX(), 0.5}, square, kTol), Side::Straddles);
}

TEST(Nishita, FaceClassesOfABoxAgainstAnAreaSource) {
  // A ceiling source facing down at z = 3 over a unit cube: the cube's top face sees the whole
  // source (H(S_f, S_e) = 1 and H(S_e, S_f) = 1: type A), its bottom never (type C).
  const ConvexPolygon source({{-1, -1, 3}, {-1, 2, 3}, {2, 2, 3}, {2, -1, 3}});
  ASSERT_TRUE(source.normal().isApprox(-Vec3::UnitZ()));
  const ConvexPolyhedron cube = unitCube();
  for (int f = 0; f < 6; ++f) {
    const Plane& plane = cube.faces()[f].plane;
    const Side faceSeesSource = nishitaH(plane, source, kTol);
    const Side sourceSeesFace = nishitaH(source.plane(), cube.facePolygon(f), kTol);
    EXPECT_EQ(sourceSeesFace, Side::Positive);
    const Side expected = plane.normal.z() > 0.5    ? Side::Positive
                          : plane.normal.z() < -0.5 ? Side::Negative
                                                    : Side::Straddles;
    EXPECT_EQ(faceSeesSource, expected);
  }
}

// The Morton key of a point, one bit at a time: bit b of cell coordinate k goes to bit 3b + k.
std::uint64_t mortonKeyBitByBit(const Vec3& p, const Vec3& lo, double scale, double cells) {
  std::uint64_t key = 0;
  for (int k = 0; k < 3; ++k) {
    const auto cell = static_cast<std::uint64_t>(std::clamp((p[k] - lo[k]) * scale, 0.0, cells));
    for (int b = 0; b < 21; ++b) key |= ((cell >> b) & 1u) << (3 * b + k);
  }
  return key;
}

// mortonOrder sorts by key with ties in input order: the same order as a stable comparison sort
// of keys interleaved bit by bit, for a grid batch (keys sharing their high bits, repeated
// points), points scattered over a room and points a few cells apart.
TEST(MortonOrder, AgreesWithAStableSortOfBitByBitKeys) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<SamplePoint> grid, scattered;
  for (int row = 0; row < 40; ++row)
    for (int column = 0; column < 300; ++column)
      grid.push_back({Vec3(0.01 * column, 2.0 + 0.01 * row, 0.75), Vec3::UnitZ(), -1});
  grid.push_back(grid[17]);  // a repeated point: equal keys keep their order
  for (int i = 0; i < 5000; ++i)
    scattered.push_back(
        {Vec3(12.0 * u(random), 8.0 * u(random), 3.0 * u(random)), Vec3::UnitZ(), -1});
  // Points a few cells apart, where the low bits of the keys decide the order.
  std::vector<SamplePoint> cellsApart = {{Vec3(1.0, 1.0, 1.0), Vec3::UnitZ(), -1}};
  const double cell = 1.0 / (double{1 << 21} - 1.0);
  for (int i = 7; i >= 0; --i)
    for (int j = 0; j < 8; ++j)
      for (int k = 7; k >= 0; --k)
        cellsApart.push_back({cell * Vec3(i + 0.5, j + 0.5, k + 0.5), Vec3::UnitZ(), -1});
  for (const std::vector<SamplePoint>& points : {grid, scattered, cellsApart}) {
    Vec3 lo = points[0].position, hi = lo;
    for (const SamplePoint& p : points) {
      lo = lo.cwiseMin(p.position);
      hi = hi.cwiseMax(p.position);
    }
    const double cells = double{1 << 21} - 1.0;
    const double scale = cells / (hi - lo).maxCoeff();
    std::vector<std::uint64_t> keys;
    for (const SamplePoint& p : points)
      keys.push_back(mortonKeyBitByBit(p.position, lo, scale, cells));
    std::vector<std::size_t> expected(points.size());
    for (std::size_t i = 0; i < expected.size(); ++i) expected[i] = i;
    std::stable_sort(expected.begin(), expected.end(),
                     [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
    EXPECT_EQ(mortonOrder(points), expected);
  }
}

}  // namespace
}  // namespace penumbra
