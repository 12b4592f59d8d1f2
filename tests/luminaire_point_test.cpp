// The point model of photometric luminaires, kernel (PoCL) and host reference, against the
// candela table at its nodes, the symmetries and formats of the files, the aim's frame, flux
// conservation over a closed box, hard shadows, and each other on a furnished room.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>

#include "grid/grid_evaluation.hpp"
#include "luminaire_test_support.hpp"
#include "photometry/photometric_frame.hpp"
#include "photometry/zonal_flux.hpp"
#include "photometry_files.hpp"
#include "scene/scene_loader.hpp"
#include "test_files.hpp"
#include "test_scenes.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;
namespace tf = photometry::testfiles;
using photometry::PhotometricType;
using photometry::TableAngles;

// Float kernels: 2^-24 per operation, angles from atan2pi; the table's values at its nodes.
constexpr double kKernelRelative = 1e-6;
// The kernel's angles are float: atan2pi and the conversion to degrees round by a few ulp
// (float ulp at 90° is 7.6e-6°), so at a node the kernel interpolates a hair into the
// neighbouring cells. Its allowance at a node: this angle times the steepest slope of the table
// there (cd per degree, to any neighbour), on top of the relative criterion.
constexpr double kKernelAngleDeg = 2e-5;
// The host reference in double.
constexpr double kReferenceRelative = 1e-12;

// A unit vector perpendicular to `d`.
Vec3 perpendicular(const Vec3& d) {
  const Vec3 other = std::abs(d.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return d.cross(other).normalized();
}

struct NodeCase {
  std::vector<SamplePoint> points;
  std::vector<double> expected;        // I(node) · cos θ / d²
  std::vector<double> angleAllowance;  // lx: kKernelAngleDeg × the table's slope × cos θ / d²
};

// The steepest |ΔI / Δangle| from node (j, k) to its neighbours in either angle (cd per degree).
double steepestSlope(const photometry::LightDistribution& d, std::size_t j, std::size_t k) {
  const std::vector<double>& planes = d.planeAnglesDeg();
  const std::vector<double>& inPlane = d.inPlaneAnglesDeg();
  const double here = d.candela(j, k);
  double slope = 0.0;
  if (k > 0)
    slope = std::max(slope, std::abs(d.candela(j, k - 1) - here) / (inPlane[k] - inPlane[k - 1]));
  if (k + 1 < inPlane.size())
    slope = std::max(slope, std::abs(d.candela(j, k + 1) - here) / (inPlane[k + 1] - inPlane[k]));
  const std::size_t m = planes.size();
  if (m > 1) {
    const auto gap = [&](std::size_t a, std::size_t b) {
      const double g = planes[b] - planes[a];
      return g > 0 ? g : g + 360.0;  // type C wraps
    };
    const std::size_t next = (j + 1) % m, previous = (j + m - 1) % m;
    if (j + 1 < m || d.periodicPlanes())
      slope = std::max(slope, std::abs(d.candela(next, k) - here) / gap(j, next));
    if (j > 0 || d.periodicPlanes())
      slope = std::max(slope, std::abs(d.candela(previous, k) - here) / gap(previous, j));
  }
  return slope;
}

// A point at every node of the luminaire's table, along the node's direction from the centre at
// distances 1.3-2.1 m, its normal tilted from the direction back to the centre.
NodeCase pointsAtNodes(const Luminaire& luminaire) {
  const photometry::LightDistribution& d = *luminaire.distribution;
  const LuminaireInstance& instance = luminaire.instances.front();
  NodeCase c;
  int index = 0;
  for (std::size_t j = 0; j < d.planeAnglesDeg().size(); ++j) {
    for (std::size_t k = 0; k < d.inPlaneAnglesDeg().size(); ++k, ++index) {
      const double plane = d.planeAnglesDeg()[j], inPlane = d.inPlaneAnglesDeg()[k];
      // The poles of types A and B (in-plane angle ±90°) lie on every plane: their plane angle
      // is whatever the rounding of the direction makes it, possibly outside the measured planes.
      if (d.type() != PhotometricType::C && std::abs(inPlane) == 90.0) continue;
      const TableAngles angles = d.type() == PhotometricType::B ? TableAngles{inPlane, plane}
                                                                : TableAngles{plane, inPlane};
      const Vec3 local = photometry::directionOf(d.type(), angles);
      const Vec3 out = instance.toScene * local;
      const double r = 1.3 + 0.2 * (index % 5);
      const Vec3 p = instance.position + r * out;
      const Vec3 n = (-out + 0.4 * perpendicular(out)).normalized();
      const double cosTheta = n.dot(-out);
      c.points.push_back(SamplePoint{p, n, -1});
      c.expected.push_back(luminaire.intensityScale * d.candela(j, k) * cosTheta / (r * r));
      c.angleAllowance.push_back(luminaire.intensityScale * kKernelAngleDeg *
                                 steepestSlope(d, j, k) * cosTheta / (r * r));
    }
  }
  return c;
}

// The largest |E − expected| / expected over points with expected > 0, and whether every point
// with expected = 0 got at most `zeroTolerance`.
struct Agreement {
  double worstRelative = 0.0;
  double worstZero = 0.0;
};

Agreement agreement(const std::vector<double>& e, const std::vector<double>& expected,
                    const std::vector<double>& allowance) {
  Agreement a;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double excess = std::max(0.0, std::abs(e[i] - expected[i]) - allowance[i]);
    if (expected[i] > 0.0)
      a.worstRelative = std::max(a.worstRelative, excess / expected[i]);
    else
      a.worstZero = std::max(a.worstZero, excess);
  }
  return a;
}

void expectNodes(const Luminaire& luminaire, const std::string& what) {
  Scene scene;
  scene.luminaires.push_back(luminaire);
  const NodeCase c = pointsAtNodes(luminaire);
  double peak = 0.0;
  for (double e : c.expected) peak = std::max(peak, e);
  const Agreement reference =
      agreement(referenceE(scene, c.points), c.expected, std::vector<double>(c.points.size(), 0.0));
  const std::vector<double> e = kernelE(scene, c.points);
  const Agreement kernel = agreement(e, c.expected, c.angleAllowance);
  const Agreement kernelRaw = agreement(e, c.expected, std::vector<double>(e.size(), 0.0));
  EXPECT_LE(reference.worstRelative, kReferenceRelative) << what;
  EXPECT_LE(reference.worstZero, kReferenceRelative * peak) << what;
  EXPECT_LE(kernel.worstRelative, kKernelRelative) << what;
  EXPECT_LE(kernel.worstZero, kKernelRelative * peak) << what;
  std::printf(
      "  %s: %zu nodes, max relative error: reference %.2e, kernel %.2e (%.2e beyond the angle "
      "allowance)\n",
      what.c_str(), c.points.size(), reference.worstRelative, kernelRaw.worstRelative,
      kernel.worstRelative);
}

const LuminaireAim kTurned{30.0, 20.0};

TEST(PointModelNodes, TypeCFromTheExampleFiles) {
  for (const char* name : {"batwing.ldt", "asymmetric-wallwasher.ies", "lambertian-panel.ldt",
                           "narrow-downlight.ies"}) {
    expectNodes(placeLuminaire({kExampleLuminaires / name, Vec3(0.3, -0.2, 2.5), kTurned, 0.8}),
                name);
  }
}

// I = 500 + 300 cos H cos V: the same at both poles of types A and B whatever the plane.
double typeABIntensity(double h, double v) {
  constexpr double kRad = std::numbers::pi / 180;
  return 500 + 300 * std::cos(h * kRad) * std::cos(v * kRad);
}

TEST(PointModelNodes, TypesBAndA) {
  TempDir dir("luminaire-nodes");
  tf::IesSpec b;
  b.type = 2;
  b.horizontal = tf::steps(-90, 90, 10);
  b.vertical = tf::steps(-90, 90, 7.5);
  b.candela = typeABIntensity;
  expectNodes(
      placeLuminaire({writeFile(dir.path(), "type-b.ies", tf::iesText(b)), Vec3(1, 2, 3), kTurned}),
      "type B");
  tf::IesSpec a;
  a.type = 3;
  a.horizontal = tf::steps(-180, 180, 15);
  a.vertical = tf::steps(-90, 90, 10);
  a.candela = typeABIntensity;
  expectNodes(placeLuminaire(
                  {writeFile(dir.path(), "type-a.ies", tf::iesText(a)), Vec3(-1, 0.5, 2), kTurned}),
              "type A");
}

// Points on a shell 1-3 m around `centre`, facing it, in random directions.
std::vector<SamplePoint> pointsAround(const Vec3& centre, int count, unsigned seed) {
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> radius(1.0, 3.0);
  std::vector<SamplePoint> points;
  for (int i = 0; i < count; ++i) {
    const Vec3 d = Vec3(normal(random), normal(random), normal(random)).normalized();
    const Vec3 n = (-d + 0.5 * perpendicular(d)).normalized();
    points.push_back(SamplePoint{centre + radius(random) * d, n, -1});
  }
  return points;
}

// f(C, γ) is symmetric about C0-C180 and C90-C270, so every symmetry can store it.
double quadrantSymmetric(double c, double g) {
  constexpr double kRad = std::numbers::pi / 180;
  const double cc = std::cos(c * kRad);
  return 300 + 200 * cc * cc * std::sin(g * kRad) + 50 * std::cos(g * kRad);
}
double rotational(double, double g) {
  return 300 + 50 * std::cos(g * std::numbers::pi / 180);
}

struct Written {
  std::string name;
  std::filesystem::path file;
};

void expectSameE(const std::vector<Written>& files, const std::string& what) {
  const std::vector<SamplePoint> points = pointsAround(Vec3(0.5, 0.5, 2.0), 200, 7);
  std::vector<double> firstReference, firstKernel;
  for (const Written& w : files) {
    Scene scene;
    scene.luminaires.push_back(placeLuminaire({w.file, Vec3(0.5, 0.5, 2.0), kTurned}));
    const std::vector<double> reference = referenceE(scene, points);
    const std::vector<double> kernel = kernelE(scene, points);
    if (firstReference.empty()) {
      firstReference = reference;
      firstKernel = kernel;
      continue;
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      ASSERT_GT(firstReference[i], 0.0);
      EXPECT_NEAR(reference[i], firstReference[i], kReferenceRelative * firstReference[i])
          << what << ": " << w.name << " against " << files.front().name << ", point " << i;
      EXPECT_NEAR(kernel[i], firstKernel[i], kKernelRelative * firstKernel[i])
          << what << ": " << w.name << " against " << files.front().name << ", point " << i;
    }
  }
}

TEST(PointModelSymmetry, EverySymmetryAndBothFormatsGiveTheSameE) {
  TempDir dir("luminaire-symmetry");
  std::vector<Written> files;
  // IES: 0-90 (quadrant), 0-180, 0-360, and LM-63-1995's 90-270; 1000 lm so that EULUMDAT's
  // cd/klm are cd.
  for (auto [name, first, last] : {std::tuple{"quadrant.ies", 0.0, 90.0},
                                   {"half.ies", 0.0, 180.0},
                                   {"full.ies", 0.0, 360.0},
                                   {"c90-c270.ies", 90.0, 270.0}}) {
    tf::IesSpec s;
    if (first == 90.0) s.versionLine = "IESNA:LM-63-1995";
    s.horizontal = tf::steps(first, last, 15);
    s.vertical = tf::steps(0, 180, 5);
    s.candela = quadrantSymmetric;
    files.push_back({name, writeFile(dir.path(), name, tf::iesText(s))});
  }
  for (int isym : {0, 2, 3, 4}) {
    tf::LdtSpec s;
    s.isym = isym;
    s.dc = 15;
    s.dg = 5;
    s.cdPerKlm = quadrantSymmetric;
    const std::string name = "isym" + std::to_string(isym) + ".ldt";
    files.push_back({name, writeFile(dir.path(), name, tf::ldtText(s))});
  }
  expectSameE(files, "quadrant-symmetric distribution");

  std::vector<Written> round;
  tf::IesSpec one;
  one.horizontal = {0};
  one.vertical = tf::steps(0, 180, 5);
  one.candela = rotational;
  round.push_back({"one-plane.ies", writeFile(dir.path(), "one-plane.ies", tf::iesText(one))});
  tf::IesSpec full = one;
  full.horizontal = tf::steps(0, 360, 15);
  round.push_back({"full.ies", writeFile(dir.path(), "round-full.ies", tf::iesText(full))});
  tf::LdtSpec isym1;
  isym1.isym = 1;
  isym1.cdPerKlm = rotational;
  round.push_back({"isym1.ldt", writeFile(dir.path(), "isym1.ldt", tf::ldtText(isym1))});
  expectSameE(round, "rotationally symmetric distribution");
}

// ---- the aim's frame

// Σ E over a 5 × 5 patch of points on each wall of a 4 × 4 × 3 m space (x0, x1, y0, y1), facing
// inwards, from a scene with one luminaire at (2, 2, 2.8).
std::array<double, 4> wallSums(const std::string& file, const LuminaireAim& aim) {
  const Luminaire luminaire = placeLuminaire({kExampleLuminaires / file, Vec3(2, 2, 2.8), aim});
  Scene scene;
  scene.luminaires.push_back(luminaire);
  std::vector<SamplePoint> points;
  const Vec3 walls[4][2] = {{Vec3(0, 2, 0), Vec3::UnitX()},
                            {Vec3(4, 2, 0), -Vec3::UnitX()},
                            {Vec3(2, 0, 0), Vec3::UnitY()},
                            {Vec3(2, 4, 0), -Vec3::UnitY()}};
  for (const auto& wall : walls) {
    const Vec3 along = Vec3::UnitZ().cross(wall[1]);
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j)
        points.push_back(SamplePoint{
            wall[0] + (i - 2) * 0.7 * along + (0.3 + 0.5 * j) * Vec3::UnitZ(), wall[1], -1});
  }
  const std::vector<double> kernel = kernelE(scene, points);
  const std::vector<double> reference = referenceE(scene, points);
  std::array<double, 4> sums{};
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(kernel[i], reference[i], 1e-5 * reference[i] + 1e-9);
    sums[i / 25] += reference[i];
  }
  return sums;
}

TEST(PointModelAim, TheWallWasherLightsTheWallItIsTurnedTo) {
  // C0 (the lobe) along (cos r, sin r, 0): r = 0 → wall x1, 90 → y1, 180 → x0, 270 → y0.
  const std::pair<double, int> cases[] = {{0, 1}, {90, 3}, {180, 0}, {270, 2}};
  for (auto [rotate, lit] : cases) {
    const std::array<double, 4> sums = wallSums("asymmetric-wallwasher.ies", {rotate, 0});
    for (int w = 0; w < 4; ++w) {
      if (w != lit) {
        EXPECT_GT(sums[lit], 2.0 * sums[w]) << "rotate " << rotate << ", wall " << w;
      }
    }
  }
}

TEST(PointModelAim, TiltSwingsTheNadirTowardsC90) {
  // Tilted 90° about C0 the downlight's beam points along the local +y (C90): wall y1; turned
  // by 90° more about z, along −x: wall x0.
  const std::pair<LuminaireAim, int> cases[] = {{{0, 90}, 3}, {{90, 90}, 0}, {{0, -90}, 2}};
  for (auto [aim, lit] : cases) {
    const std::array<double, 4> sums = wallSums("narrow-downlight.ies", aim);
    for (int w = 0; w < 4; ++w) {
      if (w != lit) {
        EXPECT_GT(sums[lit], 10.0 * sums[w])
            << "rotate " << aim.rotateDeg << ", tilt " << aim.tiltDeg << ", wall " << w;
      }
    }
  }
}

// ---- flux conservation

// Gauss–Legendre nodes and weights of order 3 on [0, 1].
TEST(PointModelFlux, TheBoxAroundALuminaireReceivesItsFlux) {
  const BoxQuadrature q = boxQuadrature(160);
  for (const char* name : {"batwing.ldt", "asymmetric-wallwasher.ies", "lambertian-panel.ldt",
                           "narrow-downlight.ies"}) {
    Scene scene;
    scene.luminaires.push_back(
        placeLuminaire({kExampleLuminaires / name, Vec3::Zero(), kTurned, 1.0}));
    const double zonal = scene.luminaires.front().zonalFluxLm();
    const double reference = q.received(referenceE(scene, q.points));
    const double kernel = q.received(kernelE(scene, q.points));
    EXPECT_NEAR(reference, zonal, 1e-3 * zonal) << name;
    EXPECT_NEAR(kernel, zonal, 1e-3 * zonal) << name;
    std::printf("  %s: zonal %.3f lm, box (reference) %.3f lm (%+.4f %%), box (kernel) %+.4f %%\n",
                name, zonal, reference, 100 * (reference / zonal - 1), 100 * (kernel / zonal - 1));
  }
}

// ---- hard shadows

TEST(PointModelShadow, ABoxBetweenLuminaireAndPointsGivesExactlyZeroBehindIt) {
  Luminaire panel =
      placeLuminaire({kExampleLuminaires / "lambertian-panel.ldt", Vec3(0, 0, 3), {}});
  Scene scene;
  scene.luminaires.push_back(panel);
  // The box [-0.5, 0.5]² × [1, 1.5]: seen from (0, 0, 3) it hides the floor where
  // max(|x|, |y|) < 1 (its top face, 1.5 m below the centre, halfway down).
  scene.solids.push_back(boxSolid(Vec3(-0.5, -0.5, 1.0), Vec3(0.5, 0.5, 1.5)));
  std::vector<SamplePoint> points;
  std::vector<bool> hidden;
  for (double x = -2.375; x < 2.4; x += 0.25)
    for (double y = -2.375; y < 2.4; y += 0.25) {
      points.push_back(SamplePoint{Vec3(x, y, 0), Vec3::UnitZ(), -1});
      hidden.push_back(std::max(std::abs(x), std::abs(y)) < 1.0);
    }
  // On the box's top face (its own solid never shades it) and under its bottom face (facing
  // away from the luminaire).
  points.push_back(SamplePoint{Vec3(0.2, 0.1, 1.5), Vec3::UnitZ(), 0});
  hidden.push_back(false);
  points.push_back(SamplePoint{Vec3(0.2, 0.1, 1.0), -Vec3::UnitZ(), 0});
  hidden.push_back(true);

  const std::vector<double> kernel = kernelE(scene, points);
  const std::vector<double> reference = referenceE(scene, points);
  int shaded = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 w = Vec3(0, 0, 3) - points[i].position;
    const double cosTheta = std::max(0.0, points[i].normal.dot(w) / w.norm());
    const double expected = hidden[i] ? 0.0 : panel.intensity(-w) * cosTheta / w.squaredNorm();
    if (hidden[i]) {
      ++shaded;
      EXPECT_EQ(kernel[i], 0.0) << points[i].position.transpose();
      EXPECT_EQ(reference[i], 0.0) << points[i].position.transpose();
    } else {
      ASSERT_GT(expected, 0.0);
      EXPECT_NEAR(kernel[i], expected, kKernelRelative * expected)
          << points[i].position.transpose();
      EXPECT_NEAR(reference[i], expected, kReferenceRelative * expected)
          << points[i].position.transpose();
    }
  }
  EXPECT_EQ(shaded, 8 * 8 + 1);
}

// ---- kernel against reference in a furnished room

TEST(PointModelKernel, AgreesWithTheReferenceInTheExampleOffice) {
  const Scene scene = loadScene(PENUMBRA_SOURCE_DIR "/data/luminaires-office.yaml");
  ASSERT_EQ(scene.luminaires.size(), 3u);
  double worst = 0.0, largest = 0.0;
  std::size_t points = 0;
  for (const CalculationGrid& grid : scene.grids) {
    IlluminanceEngine engine(cpuDevice(), scene);
    const GridEvaluation kernel = evaluateGrid(
        scene, grid, [&](std::span<const SamplePoint> p) { return engine.illuminance(p); }, 4096);
    const std::vector<double> reference = referenceE(scene, kernel.samples.points);
    for (std::size_t i = 0; i < reference.size(); ++i) {
      if (kernel.samples.inside[i] >= 0) continue;
      largest = std::max(largest, reference[i]);
      worst = std::max(
          worst, std::abs(kernel.illuminance[i] - reference[i]) / std::max(reference[i], 1e-3));
      ++points;
    }
  }
  EXPECT_LE(worst, kKernelRelative);
  std::printf("  %zu points, Emax %.1f lx, kernel vs reference: %.2e relative (max)\n", points,
              largest, worst);
}

}  // namespace
}  // namespace penumbra
