// Shadow volumes (Nishita §2.1-2.3): face classes, and umbra / penumbra volumes held against the
// exact oracle (host/reference/pyramid_oracle) on random and near-degenerate configurations.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "geometry/tolerance.hpp"
#include "reference/pyramid_oracle.hpp"
#include "shadow/face_class.hpp"
#include "shadow/shadow_volume.hpp"

namespace penumbra {
namespace {

ConvexPolygon square(double half, double height) {
  return ConvexPolygon(
      {{-half, -half, height}, {half, -half, height}, {half, half, height}, {-half, half, height}});
}

// ---------------------------------------------------------------------------------------------
// Face classes (eq. 3 and 4).

TEST(FaceClass, FloorUnderACeilingPanelIsA) {
  const ConvexPolygon panel = square(0.5, 3.0).reversed();  // emits downwards
  EXPECT_EQ(classifyFace(square(2.0, 0.0), panel, 1e-9), FaceClass::A);
}

TEST(FaceClass, AWallBesideThePanelIsCutByItsPlane) {
  const ConvexPolygon panel = square(0.5, 3.0).reversed();
  // The plane x = 0, facing +x, cuts the panel (it spans x in [-0.5, 0.5]).
  const ConvexPolygon wall({{0, -2, 0}, {0, 2, 0}, {0, 2, 2}, {0, -2, 2}});
  ASSERT_GT(wall.normal().x(), 0.0);
  EXPECT_EQ(classifyFace(wall, panel, 1e-9), FaceClass::B);
}

TEST(FaceClass, FacesThatSeeNothingAreC) {
  const ConvexPolygon panel = square(0.5, 3.0).reversed();
  // The ceiling's underside is level with the panel; a face above the panel is behind it; a
  // floor facing down has the panel behind it.
  EXPECT_EQ(classifyFace(square(2.0, 4.0), panel, 1e-9), FaceClass::C);
  EXPECT_EQ(classifyFace(square(2.0, 0.0).reversed(), panel, 1e-9), FaceClass::C);
}

TEST(FaceClass, PolyhedronSourcesLightEveryFaceThatSeesThem) {
  const ConvexPolyhedron globe = ConvexPolyhedron::box({-0.2, -0.2, 2.0}, {0.2, 0.2, 2.4});
  EXPECT_EQ(classifyFace(square(2.0, 0.0), globe, 1e-9), FaceClass::A);
  EXPECT_EQ(classifyFace(square(2.0, 2.2), globe, 1e-9), FaceClass::B);  // cuts the globe
  EXPECT_EQ(classifyFace(square(2.0, 3.0), globe, 1e-9), FaceClass::C);  // above, facing up
}

TEST(FaceClass, PointClassesAgreeWithTheHorizon) {
  const ConvexPolygon panel = square(0.5, 3.0).reversed();
  const Plane emission = panel.plane();
  const auto& q = panel.vertices();
  EXPECT_EQ(classifyPoint({0, 0, 0}, {0, 0, 1}, q, emission), FaceClass::A);
  EXPECT_EQ(classifyPoint({0, 0, 1}, {1, 0, 0}, q, emission), FaceClass::B);
  EXPECT_EQ(classifyPoint({0, 0, 1}, {0, 0, -1}, q, emission), FaceClass::C);
  EXPECT_EQ(classifyPoint({0, 0, 3.5}, {0, 0, 1}, q, emission), FaceClass::C);  // behind it
  EXPECT_EQ(classifyPoint({2, 0, 3}, {0, 0, -1}, q, emission), FaceClass::C);   // level with it
}

// ---------------------------------------------------------------------------------------------
// Random configurations against the oracle.

class RandomScenes {
 public:
  explicit RandomScenes(std::uint64_t seed) : rng_(seed) {}

  double uniform(double lo, double hi) { return std::uniform_real_distribution<>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<>(lo, hi)(rng_); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }

  Eigen::Matrix3d rotation() {
    Eigen::Quaterniond q(normal(), normal(), normal(), normal());
    return q.normalized().toRotationMatrix();
  }
  Vec3 direction() { return Vec3(normal(), normal(), normal()).normalized(); }

  // A convex polygon source: a regular n-gon or a rectangle, anywhere, facing anywhere.
  ConvexPolygon polygonSource(const Eigen::Matrix3d& frame, const Vec3& centre) {
    std::vector<Vec3> local;
    if (chance(0.5)) {
      const double a = uniform(0.1, 2.0), b = uniform(0.1, 2.0);
      local = {{-a, -b, 0}, {a, -b, 0}, {a, b, 0}, {-a, b, 0}};
    } else {
      const int sides = integer(3, 8);
      const double r = uniform(0.1, 1.5), phase = uniform(0.0, 6.283);
      for (int i = 0; i < sides; ++i) {
        const double t = phase + 6.283185307179586 * i / sides;
        local.push_back({r * std::cos(t), r * std::sin(t), 0.0});
      }
    }
    std::vector<Vec3> world;
    for (const Vec3& v : local) world.push_back(centre + frame * v);
    return ConvexPolygon(world);
  }

  // A box, or the hull of a few random points, of random size and orientation.
  ConvexPolyhedron solid(const Vec3& centre, const Eigen::Matrix3d& frame, bool thin) {
    std::vector<Vec3> points;
    if (chance(0.7)) {
      Vec3 half(uniform(0.02, 1.0), uniform(0.02, 1.0), uniform(0.02, 1.0));
      if (thin) half[integer(0, 2)] = 1e-5;
      for (int i = 0; i < 8; ++i)
        points.push_back(centre + frame * Vec3((i & 1 ? 1 : -1) * half.x(),
                                               (i & 2 ? 1 : -1) * half.y(),
                                               (i & 4 ? 1 : -1) * half.z()));
    } else {
      const double r = uniform(0.05, 1.0);
      const int count = integer(4, 12);
      for (int i = 0; i < count; ++i) points.push_back(centre + r * direction());
    }
    return ConvexPolyhedron::hull(points, 1e-9);
  }

 private:
  double normal() { return std::normal_distribution<>(0.0, 1.0)(rng_); }
  std::mt19937_64 rng_;
};

struct OracleTally {
  long points = 0;
  long mustShade = 0, missed = 0;            // oracle: the pyramid meets the occluder
  long calledPenumbra = 0, falseAlarms = 0;  // volume says "may shade"; oracle: clearly clear
  long fullyHidden = 0, calledUmbra = 0;     // oracle: every source sample hidden; volume: umbra
  long wrongUmbra = 0;                       // umbra, yet a source sample is clearly visible
  long degeneratePairs = 0;
};

// Source samples for the umbra check: the vertices and a lattice over the polygon (or every
// face of a polyhedron).
std::vector<Vec3> sourceSamples(const std::vector<ConvexPolygon>& faces) {
  std::vector<Vec3> samples;
  for (const ConvexPolygon& face : faces) {
    const Vec3 c = face.centroid();
    for (const Vec3& v : face.vertices())
      for (int k = 0; k <= 6; ++k) samples.push_back(c + (v - c) * (k / 6.0));
    const auto& vs = face.vertices();
    for (std::size_t i = 0; i < vs.size(); ++i)
      for (int k = 1; k < 6; ++k)
        samples.push_back(vs[i] + (vs[(i + 1) % vs.size()] - vs[i]) * (k / 6.0));
  }
  return samples;
}

void checkPoint(const Vec3& p, const std::vector<Vec3>& sourceVertices,
                const std::vector<Vec3>& samples, const ConvexPolyhedron& occluder,
                const ShadowVolume& volume, double margin, double clear, OracleTally& tally) {
  ++tally.points;
  const double sep = pyramidSeparation(p, sourceVertices, occluder, 1e-12);
  const bool mayShade = volume.mayShade(p, margin);
  if (sep < -clear) {
    ++tally.mustShade;
    if (!mayShade) {
      ++tally.missed;
      if (tally.missed <= 5)
        std::printf("missed: P = (%.9g, %.9g, %.9g), separation %.3g\n", p.x(), p.y(), p.z(), sep);
    }
  }
  if (mayShade) {
    ++tally.calledPenumbra;
    if (sep > clear) ++tally.falseAlarms;
  }
  bool anyVisible = false, allHidden = true;
  for (const Vec3& s : samples) {
    if (segmentClears(p, s, occluder, clear)) anyVisible = true;
    if (segmentClears(p, s, occluder, -clear)) allHidden = false;
  }
  if (allHidden) ++tally.fullyHidden;
  if (volume.hides(p, margin)) {
    ++tally.calledUmbra;
    if (anyVisible) {
      ++tally.wrongUmbra;
      if (tally.wrongUmbra <= 5)
        std::printf("wrong umbra: P = (%.9g, %.9g, %.9g)\n", p.x(), p.y(), p.z());
    }
  }
}

// Points for one (source, occluder) pair: random ones around, and ones placed within 1e-9 to
// 1e-3 m of the volumes' planes (the near-degenerate cases: exactly where a test can err).
// A third of them lie beyond the occluder as seen from the source, where its shadow falls.
std::vector<Vec3> probePoints(RandomScenes& random, const Vec3& centre, const Vec3& occluderCentre,
                              const ShadowVolume& volume, int count) {
  std::vector<Vec3> points;
  for (int i = 0; i < count; ++i) {
    Vec3 p = centre + Vec3(random.uniform(-4, 4), random.uniform(-4, 4), random.uniform(-4, 4));
    if (i % 3 == 0)
      p = occluderCentre + random.uniform(0.2, 3.0) * (occluderCentre - centre) +
          Vec3(random.uniform(-1, 1), random.uniform(-1, 1), random.uniform(-1, 1));
    const auto& planes = random.chance(0.5) ? volume.penumbra : volume.umbra;
    if (!planes.empty() && random.chance(0.4)) {
      const Plane& plane = planes[random.integer(0, static_cast<int>(planes.size()) - 1)];
      const double offsets[] = {1e-9, 1e-6, 1e-3};
      p -= (plane.signedDistance(p) +
            (random.chance(0.5) ? 1 : -1) * offsets[random.integer(0, 2)]) *
           plane.normal;
    }
    points.push_back(p);
  }
  return points;
}

void printTally(const char* what, const OracleTally& t) {
  std::printf(
      "%s: %ld points; %ld must shade, %ld missed; %ld called penumbra, %ld false alarms "
      "(%.2f %%); %ld fully hidden, %ld called umbra (%.1f %% of hidden), %ld wrong umbra; "
      "%ld pairs with no umbra claimed\n",
      what, t.points, t.mustShade, t.missed, t.calledPenumbra, t.falseAlarms,
      100.0 * t.falseAlarms / std::max(1L, t.calledPenumbra), t.fullyHidden, t.calledUmbra,
      100.0 * t.calledUmbra / std::max(1L, t.fullyHidden), t.wrongUmbra, t.degeneratePairs);
}

// The margins the checks use: the volumes are tested with the host's length tolerance; the
// oracle's verdicts count only when clear of the boundary by 1e-7 m (100 × the tolerance).
constexpr double kMargin = 1e-9 * 10.0;
constexpr double kClear = 1e-7;

// One (source, occluder) pair: builds the volumes and checks 50 probe points, skipping those the
// source cannot light (`unlit`).
template <class Unlit>
void checkPair(RandomScenes& random, const Vec3& centre, const auto& source,
               const std::vector<Vec3>& samples, const ConvexPolyhedron& occluder,
               const Tolerance& tolerance, Unlit unlit, OracleTally& tally) {
  const ShadowVolume volume = shadowVolume(source, occluder, tolerance);
  ASSERT_FALSE(volume.penumbra.empty());
  if (volume.umbra.empty()) ++tally.degeneratePairs;
  for (const Vec3& p : probePoints(random, centre, occluder.centroid(), volume, 50)) {
    if (unlit(p)) continue;
    checkPoint(p, source.vertices(), samples, occluder, volume, kMargin, kClear, tally);
  }
}

void expectOracleAgrees(const OracleTally& tally, long points, long mustShade, long umbra) {
  EXPECT_GE(tally.points, points);
  EXPECT_GT(tally.mustShade, mustShade);
  EXPECT_EQ(tally.missed, 0);
  EXPECT_GT(tally.calledUmbra, umbra);
  EXPECT_EQ(tally.wrongUmbra, 0);
}

TEST(ShadowVolume, AreaSourcesAgainstTheOracle) {
  RandomScenes random(20261123);
  const Tolerance tolerance{kMargin};
  OracleTally tally;
  for (int pair = 0; pair < 2000; ++pair) {
    const Eigen::Matrix3d frame = random.rotation();
    const Vec3 centre(random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3));
    const ConvexPolygon source = random.polygonSource(frame, centre);
    const Vec3 m = source.normal();
    // Where the occluder goes: in front (most), touching or crossing the source plane, or behind
    // it; aligned with the source's frame (edges parallel to its edges) or turned.
    const int placement = random.integer(0, 9);
    double along = random.uniform(0.05, 3.0);
    if (placement == 0) along = random.uniform(-0.5, 0.5);  // crossing the plane
    if (placement == 1) along = -random.uniform(1.5, 3.0);  // behind: nothing is left
    const Vec3 lateral = frame * Vec3(random.uniform(-2, 2), random.uniform(-2, 2), 0.0);
    const Eigen::Matrix3d turn = random.chance(0.3) ? frame : random.rotation();
    ConvexPolyhedron solid = random.solid(centre + lateral + along * m, turn, random.chance(0.1));
    if (placement == 2) {  // resting on the source plane: its lowest vertex exactly on it
      double lowest = 1e300;
      for (const Vec3& v : solid.vertices()) lowest = std::min(lowest, m.dot(v - centre));
      std::vector<Vec3> moved;
      for (const Vec3& v : solid.vertices()) moved.push_back(v - lowest * m);
      solid = ConvexPolyhedron::hull(moved, 1e-9);
    }
    const ConvexPolyhedron occluder = solid.clipped(source.plane().flipped(), tolerance.length);
    if (occluder.empty()) {  // wholly behind the source: it casts nothing
      EXPECT_TRUE(shadowVolume(source, occluder, tolerance).penumbra.empty());
      continue;
    }
    // Points behind the source get no light to block.
    checkPair(
        random, centre, source, sourceSamples({source}), occluder, tolerance,
        [&](const Vec3& p) { return source.plane().signedDistance(p) <= kClear; }, tally);
  }
  printTally("area sources", tally);
  expectOracleAgrees(tally, 50000, 10000, 1000);
}

TEST(ShadowVolume, PolyhedronSourcesAgainstTheOracle) {
  RandomScenes random(7);
  const Tolerance tolerance{kMargin};
  OracleTally tally;
  for (int pair = 0; pair < 1200; ++pair) {
    const Vec3 centre(random.uniform(-3, 3), random.uniform(-3, 3), random.uniform(-3, 3));
    const ConvexPolyhedron source = random.solid(centre, random.rotation(), false);
    if (source.empty()) continue;
    // The occluder: anywhere around, but not meeting the source.
    const Vec3 at = centre + random.uniform(0.8, 3.0) * random.direction();
    const ConvexPolyhedron occluder = random.solid(at, random.rotation(), random.chance(0.1));
    if (occluder.empty() || separation(source, occluder) <= 1e-6) continue;
    std::vector<ConvexPolygon> faces;
    for (int f = 0; f < static_cast<int>(source.faces().size()); ++f)
      faces.push_back(source.facePolygon(f));
    // Points on or in the source are not lit by it.
    const auto onOrInSource = [&](const Vec3& p) {
      return std::all_of(source.faces().begin(), source.faces().end(),
                         [&](const auto& f) { return f.plane.signedDistance(p) <= kClear; });
    };
    checkPair(random, centre, source, sourceSamples(faces), occluder, tolerance, onOrInSource,
              tally);
  }
  printTally("polyhedron sources", tally);
  expectOracleAgrees(tally, 40000, 5000, 500);
}

// A window in a wall: the wall's pieces beside the opening touch the source along its edges.
// Their penumbra volume must still be the half-space behind the reveal, not the whole room.
TEST(ShadowVolume, ARevealTouchingTheWindowShadesOnlyBehindItself) {
  const ConvexPolygon window({{0, 1, 1}, {0, 2, 1}, {0, 2, 2}, {0, 1, 2}});  // faces +x
  ASSERT_GT(window.normal().x(), 0.0);
  const ConvexPolyhedron reveal = ConvexPolyhedron::box({0, 0, 0}, {0.3, 1, 3});  // y < 1 side
  const ShadowVolume volume = shadowVolume(window, reveal, Tolerance{1e-9});
  EXPECT_TRUE(volume.mayShade({2.0, 0.5, 1.5}, 1e-9));   // behind the reveal's plane y = 1
  EXPECT_FALSE(volume.mayShade({2.0, 1.5, 1.5}, 1e-9));  // in front of the window
  EXPECT_FALSE(volume.mayShade({0.5, 1.01, 0.2}, 1e-9));
  EXPECT_TRUE(volume.hides({0.2, -2.0, 1.5}, 1e-9));  // beside the wall, level with the window
}

}  // namespace
}  // namespace penumbra
