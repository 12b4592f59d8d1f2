// The area model of photometric luminaires (host reference, double): the closed-form moments
// against Gauss–Legendre quadrature over the visible opening, a Lambertian file against the
// Lambertian rect source of the same flux, the point model far away, flux conservation over a
// closed box, and the fit and its fallback. On the device (kernels/luminance_moments.cl): the
// kernel's area model against the host reference on every path, and the Lambertian file against
// the kernel's rect source.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>

#include "geometry/tolerance.hpp"
#include "luminaire_test_support.hpp"
#include "photometry/luminous_opening.hpp"
#include "photometry/nonnegative_least_squares.hpp"
#include "photometry_files.hpp"
#include "reference/cosine_moments.hpp"
#include "reference/exact_illuminance.hpp"
#include "reference/opening_illuminance.hpp"
#include "reference/visible_boundary.hpp"
#include "sanitized_build.hpp"
#include "test_files.hpp"
#include "test_scenes.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;
namespace tf = photometry::testfiles;

constexpr double kPi = std::numbers::pi;

// ---- quadrature over axis-aligned rectangles of the plane z = height

constexpr double kGauss5Nodes[5] = {-0.9061798459386640, -0.5384693101056831, 0.0,
                                    0.5384693101056831, 0.9061798459386640};
constexpr double kGauss5Weights[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                      0.4786286704993665, 0.2369268850561891};

struct Rect2 {
  double x0, y0, x1, y1;
};

// ∫ f(x) dA over `rect` at z = height: composite 5-point Gauss–Legendre, panels × panels cells.
template <typename F>
double integrateRect(const Rect2& rect, double height, int panels, F f) {
  const double hx = (rect.x1 - rect.x0) / panels, hy = (rect.y1 - rect.y0) / panels;
  double sum = 0.0;
  for (int i = 0; i < panels; ++i)
    for (int j = 0; j < panels; ++j)
      for (int a = 0; a < 5; ++a)
        for (int b = 0; b < 5; ++b) {
          const double x = rect.x0 + hx * (i + 0.5 + 0.5 * kGauss5Nodes[a]);
          const double y = rect.y0 + hy * (j + 0.5 + 0.5 * kGauss5Nodes[b]);
          sum += 0.25 * kGauss5Weights[a] * kGauss5Weights[b] * hx * hy * f(Vec3(x, y, height));
        }
  return sum;
}

// The geometry of the quadrature cases: an opening in the plane z = 3 facing down, the
// rectangle [-0.3, 0.3] × [-0.15, 0.15]; a point P below it; a slab over x >= -0.1, y >= -0.2
// (z in [1.5, 1.6]) that hides the corner of the opening beyond its shadow's edges.
constexpr double kHeight = 3.0;
constexpr Rect2 kOpening{-0.3, -0.15, 0.3, 0.15};
const Vec3 kPoint(-0.2, -0.3, 0.0);
const Vec3 kSlabMin(-0.1, -0.2, 1.5), kSlabMax(5.0, 5.0, 1.6);

// The slab's shadow on the opening's plane, seen from kPoint: x >= xs and y >= ys (the slab's
// near edges at its top face, the farther from P, project the farthest in).
void slabShadow(double& xs, double& ys) {
  const double k = kHeight / kSlabMax.z();
  xs = kPoint.x() + (kSlabMin.x() - kPoint.x()) * k;
  ys = kPoint.y() + (kSlabMin.y() - kPoint.y()) * k;
}

// The visible opening: the rectangle minus the corner x >= xs, y >= ys, as two rectangles.
std::vector<Rect2> visibleRects() {
  double xs, ys;
  slabShadow(xs, ys);
  return {{kOpening.x0, kOpening.y0, kOpening.x1, ys}, {kOpening.x0, ys, xs, kOpening.y1}};
}

ConvexPolygon openingPolygon() {
  // Clockwise seen from above: the normal is −z.
  return ConvexPolygon(
      {Vec3(kOpening.x0, kOpening.y0, kHeight), Vec3(kOpening.x0, kOpening.y1, kHeight),
       Vec3(kOpening.x1, kOpening.y1, kHeight), Vec3(kOpening.x1, kOpening.y0, kHeight)});
}

// ∫ (w·ω)^k (n·ω) dω over `rects` by quadrature: dω = (w·ω) dA / r² for the plane's w = +z.
double quadratureMoment(const std::vector<Rect2>& rects, const Vec3& n, int k) {
  double sum = 0.0;
  for (const Rect2& r : rects) {
    sum += integrateRect(r, kHeight, 24, [&](const Vec3& x) {
      const Vec3 d = x - kPoint;
      const double r2 = d.squaredNorm();
      const Vec3 omega = d / std::sqrt(r2);
      const double g = omega.z();
      return std::pow(g, k) * n.dot(omega) * g / r2;
    });
  }
  return sum;
}

TEST(AreaModelMoments, MatchQuadratureOverTheVisibleOpeningToOrderTwelve) {
  Scene scene;
  scene.solids.push_back(boxSolid(kSlabMin, kSlabMax));
  const Vec3 n = Vec3(0.3, 0.2, 1.0).normalized();
  const ConvexPolygon polygon = openingPolygon();
  const SamplePoint point{kPoint, n, -1};
  const double tolerance = 1e-9;
  const std::vector<VisibleArc> open =
      visibleBoundary(polygon, FaceFrame::of(polygon), point, Scene{}, tolerance);
  const std::vector<VisibleArc> hidden =
      visibleBoundary(polygon, FaceFrame::of(polygon), point, scene, tolerance);
  const int order = 12;
  const std::vector<double> exactOpen = cosineMoments(open, Vec3::UnitZ(), n, order);
  const std::vector<double> exactHidden = cosineMoments(hidden, Vec3::UnitZ(), n, order);
  for (int k = 0; k <= order; ++k) {
    const double qOpen = quadratureMoment({kOpening}, n, k);
    const double qHidden = quadratureMoment(visibleRects(), n, k);
    EXPECT_NEAR(exactOpen[k], qOpen, 1e-5 * qOpen) << "k = " << k;
    EXPECT_NEAR(exactHidden[k], qHidden, 1e-5 * qHidden) << "k = " << k;
    EXPECT_LT(qHidden, 0.9 * qOpen);  // the slab hides a real part
    std::printf("  k = %2d: open %.6e (%+.1e), occluded %.6e (%+.1e)\n", k, exactOpen[k],
                exactOpen[k] / qOpen - 1, exactHidden[k], exactHidden[k] / qHidden - 1);
  }
}

// ---- luminaires from files

// A rotationally symmetric IES file (type C, one plane) of `candela`(γ), γ = 0..180 by 1°, with a
// rectangular opening of `length` (C0-C180) × `width` (C90-C270) m.
std::filesystem::path writeSymmetricIes(const TempDir& dir, const std::string& name, double length,
                                        double width,
                                        const std::function<double(double)>& candela) {
  tf::IesSpec spec;
  spec.vertical = tf::steps(0, 180, 1);
  spec.horizontal = {0};
  spec.width = width;
  spec.length = length;
  spec.candela = [&](double, double v) { return candela(v); };
  return writeFile(dir.path(), name, tf::iesText(spec));
}

constexpr double kI0 = 1000.0;  // cd at the nadir (lamp lumens 1000: the table as written)

double lambertianCandela(double gammaDeg) {
  return tf::lambertian(kI0, gammaDeg);
}

// Points over a floor and a wall around a luminaire at (1, 0.5, 3), with a box that shades part
// of the floor and a slab that shades part of the wall.
std::vector<SamplePoint> roomPoints() {
  std::vector<SamplePoint> points;
  for (double x = -1.45; x < 3.5; x += 0.1)
    for (double y = -1.45; y < 2.5; y += 0.1) points.push_back({Vec3(x, y, 0), Vec3::UnitZ(), -1});
  for (double y = -1.45; y < 2.5; y += 0.1)
    for (double z = 0.05; z < 3.0; z += 0.1)
      points.push_back({Vec3(3.5, y, z), -Vec3::UnitX(), -1});
  return points;
}

Scene roomSolids() {
  Scene scene;
  scene.solids.push_back(boxSolid(Vec3(0.6, 0.2, 0.7), Vec3(1.3, 0.9, 1.4), "table"));
  scene.solids.push_back(boxSolid(Vec3(2.6, -0.4, 1.2), Vec3(3.2, 0.6, 1.3), "shelf"));
  return scene;
}

const LuminaireAim kTurned{30.0, 20.0};

// The room with a Lambertian file's luminaire (I = I0 cos γ, a 0.6 × 0.3 m opening unless given),
// turned, as the area model.
Scene roomWithLambertianLuminaire(const TempDir& dir, double length = 0.6, double width = 0.3) {
  const auto file =
      writeSymmetricIes(dir, "lambertian-" + std::to_string(std::lround(length * 1000)) + "mm.ies",
                        length, width, lambertianCandela);
  Scene area = roomSolids();
  area.luminaires.push_back(
      placeLuminaire({file, Vec3(1.0, 0.5, 3.0), kTurned, 1.0, LuminaireModel::Area}));
  return area;
}

TEST(AreaModelLambertian, EqualsTheRectSourceOfTheSameFluxOccludedOrNot) {
  TempDir dir("luminaire-area");
  const Scene area = roomWithLambertianLuminaire(dir);
  const Luminaire& luminaire = area.luminaires.front();
  ASSERT_TRUE(luminaire.opening.has_value());
  EXPECT_EQ(luminaire.opening->fit.order(), 0);
  EXPECT_FALSE(luminaire.opening->subdivided());
  EXPECT_LT(luminaire.opening->fit.peakRelativeError, 1e-12);

  // The Lambertian source of the same flux (π I0) over the same rectangle: L = π I0 / (π A).
  const ConvexPolygon polygon = placedOpening(*luminaire.opening, luminaire.instances.front());
  Scene rect = roomSolids();
  rect.sources.push_back(areaSource(polygon.vertices(), kPi * kI0 / (kPi * polygon.area())));
  EXPECT_NEAR(polygon.area(), 0.18, 1e-12);

  const std::vector<SamplePoint> points = roomPoints();
  const std::vector<double> fromArea = referenceE(area, points);
  const std::vector<double> fromRect = exactIlluminance(rect, points).front();
  int shaded = 0, lit = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (fromRect[i] == 0.0) {
      EXPECT_EQ(fromArea[i], 0.0) << points[i].position.transpose();
      continue;
    }
    ++lit;
    EXPECT_NEAR(fromArea[i], fromRect[i], 1e-6 * fromRect[i]) << points[i].position.transpose();
  }
  // The table and the shelf shade part of the floor and wall: some points see a part only.
  const std::vector<double> unshaded = exactIlluminance(
                                           [&] {
                                             Scene s;
                                             s.sources = rect.sources;
                                             return s;
                                           }(),
                                           points)
                                           .front();
  for (std::size_t i = 0; i < points.size(); ++i) {
    // Solids only take light away. The grid includes (0.35, 0.65, 0), where the table's shadow
    // polygon projects one vertex twice, 1e-16 apart (visible_boundary.cpp merges them).
    EXPECT_GE(fromRect[i], 0.0) << points[i].position.transpose();
    EXPECT_LE(fromRect[i], unshaded[i] * (1 + 1e-12)) << points[i].position.transpose();
    if (fromRect[i] < 0.999 * unshaded[i]) ++shaded;
  }
  EXPECT_GT(shaded, 100);
  EXPECT_GT(lit, 1000);
}

TEST(AreaModelFarField, MeetsThePointModelBeyondFiveTimesTheOpening) {
  TempDir dir("luminaire-area");
  const auto file = writeSymmetricIes(dir, "lambertian.ies", 0.6, 0.3, lambertianCandela);
  const Vec3 centre(0, 0, 0);
  Scene area, point;
  area.luminaires.push_back(placeLuminaire({file, centre, kTurned, 1.0, LuminaireModel::Area}));
  point.luminaires.push_back(placeLuminaire({file, centre, kTurned, 1.0, LuminaireModel::Point}));
  const Mat3 toScene = aimRotation(kTurned);
  const double size = std::hypot(0.6, 0.3);
  // Directions up to 80° from the nadir at five times the opening's diagonal. The photometric
  // distance rule is for the illuminance on the plane facing the luminaire: asserted there within
  // 60° of the nadir. Towards grazing emission (γ 70-80°), and on a plane turned away from the
  // luminaire (the luminaire's own axis as normal: a floor under it, where cos θ varies across the
  // opening as well), the difference is larger; both are printed.
  std::vector<SamplePoint> points;
  std::vector<int> kind;  // 0: facing, γ <= 60°; 1: facing, grazing; 2: the axis as normal
  for (double gamma = 0; gamma <= 80; gamma += 10)
    for (double c = 0; c < 360; c += 30) {
      const double g = gamma * kPi / 180, a = c * kPi / 180;
      const Vec3 local(std::sin(g) * std::cos(a), std::sin(g) * std::sin(a), -std::cos(g));
      const Vec3 d = toScene * local;
      const Vec3 p = centre + 5.0 * size * d;
      points.push_back({p, -d, -1});
      kind.push_back(gamma <= 60 ? 0 : 1);
      points.push_back({p, toScene * Vec3::UnitZ(), -1});
      kind.push_back(2);
    }
  const std::vector<double> a = referenceE(area, points), q = referenceE(point, points);
  double worst[3] = {0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_GT(q[i], 0.0);
    const int k = kind[i];
    worst[k] = std::max(worst[k], std::abs(a[i] / q[i] - 1));
    if (k == 0) {
      EXPECT_NEAR(a[i], q[i], 0.01 * q[i]) << points[i].position.transpose();
    }
  }
  std::printf(
      "  largest |area / point − 1| at 5 × the diagonal: facing, γ <= 60°: %.3e; facing, γ 70-80°: "
      "%.3e; the axis as normal: %.3e\n",
      worst[0], worst[1], worst[2]);
}

// The fitted distribution's flux: ∫ A cos φ L(cos φ) dω over the lower hemisphere =
// 2π A Σ c_k / (k + 2), times the luminaire's scale.
double fittedFlux(const Luminaire& luminaire) {
  const photometry::LuminanceFit& fit = luminaire.opening->fit;
  double sum = 0.0;
  for (int k = 0; k <= fit.order(); ++k) sum += fit.coefficients[k] / (k + 2.0);
  return luminaire.intensityScale * 2 * kPi * fit.openingAreaM2 * sum;
}

TEST(AreaModelFlux, TheBoxAroundALuminaireReceivesItsFlux) {
  const BoxQuadrature q = boxQuadrature(60, 2.0);
  // Fitted (the fit's flux) and subdivided (the batwing's C0 and C90 planes differ: the table's
  // whole flux through its cells).
  for (const char* name : {"lambertian-panel.ldt", "narrow-downlight.ies", "batwing.ldt"}) {
    Scene scene;
    scene.luminaires.push_back(placeLuminaire(
        {kExampleLuminaires / name, Vec3::Zero(), kTurned, 0.8, LuminaireModel::Area}));
    const Luminaire& luminaire = scene.luminaires.front();
    ASSERT_TRUE(luminaire.opening.has_value());
    const LuminaireOpening& opening = *luminaire.opening;
    const double zonal = luminaire.zonalFluxLm() * luminaire.maintenanceFactor;
    const double expected = opening.subdivided() ? zonal : fittedFlux(luminaire);
    const double received = q.received(referenceE(scene, q.points));
    EXPECT_NEAR(received, expected, 1e-3 * expected) << name;
    std::printf(
        "  %s: order %d, fit error %.2e of the peak, cells %d x %d; box %.3f lm, expected %.3f lm "
        "(%+.4f %%); zonal %.3f lm\n",
        name, opening.fit.order(), opening.fit.peakRelativeError, opening.partsAlongLength,
        opening.partsAlongWidth, received, expected, 100 * (received / expected - 1), zonal);
  }
}

// ---- the fit

// A spot over an even glow, L = c (1 + cos²⁴φ) (half the peak luminance at 13.6° off the axis):
// the least-squares polynomials of order <= 12 cancel or miss it; it is a sum of two nonnegative
// powers.
double spotCandela(double gammaDeg) {
  const double g = std::cos(gammaDeg * kPi / 180);
  return gammaDeg < 90 ? kI0 * g * (1 + std::pow(g, 24)) / 2 : 0.0;
}

TEST(AreaModelFit, NonnegativeLeastSquaresSolvesASmallCaseByHand) {
  // min |A x − b|, x >= 0, with A = [1 0; 0 1; 1 1], b = (1, −1, 0): the unconstrained solution is
  // (1, −1); with x_2 = 0, (x_1 − 1)² + x_1² is least at x_1 = 1/2. Columns of different scale
  // (the second times 1e6) give the same point.
  Eigen::MatrixXd a(3, 2);
  a << 1, 0, 0, 1e6, 1, 1e6;
  const Eigen::VectorXd x = photometry::nonnegativeLeastSquares(a, Eigen::Vector3d(1, -1, 0));
  EXPECT_NEAR(x(0), 0.5, 1e-15);
  EXPECT_EQ(x(1), 0.0);
}

TEST(AreaModelFit, ASpotIsASumOfNonnegativePowers) {
  TempDir dir("luminaire-area");
  const double area = 0.1 * 0.1;
  const auto file = writeSymmetricIes(dir, "spot.ies", 0.1, 0.1, spotCandela);
  const Luminaire luminaire = placeLuminaire({file, Vec3::Zero(), {}, 1.0, LuminaireModel::Area});
  // Asked for rounding, the fit finds the two powers.
  const photometry::LuminanceFit exact =
      photometry::fitLuminance(*luminaire.distribution, area, 1e-9);
  const double c = kI0 / 2 / area;
  ASSERT_EQ(exact.order(), 24);
  for (int k = 0; k <= 24; ++k) {
    const double expected = k == 0 || k == 24 ? c : 0.0;
    EXPECT_NEAR(exact.coefficients[k], expected, 1e-7 * c) << "k = " << k;
  }
  EXPECT_LT(exact.peakRelativeError, 1e-9);
  // Within the area model's tolerance a lower highest power may do; every coefficient is
  // nonnegative (conditioning 1) and the opening is integrated, not split.
  const photometry::LuminanceFit& fit = luminaire.opening->fit;
  EXPECT_FALSE(luminaire.opening->subdivided());
  EXPECT_GT(fit.order(), photometry::kLuminanceFitMaxOrder);
  EXPECT_LE(fit.order(), 24);
  EXPECT_LE(fit.peakRelativeError, photometry::kLuminanceFitTolerance);
  for (double coefficient : fit.coefficients) EXPECT_GE(coefficient, 0.0);
  EXPECT_NEAR(fit.conditioning(), 1.0, 1e-12);
}

TEST(AreaModelFit, TheExampleDownlightIsTwoNonnegativePowers) {
  // I = I0 (0.97 cos⁴⁰γ + 0.03 cos γ) from an 80 mm disk: L = I / (A cos γ) is 0.03 + 0.97 cos³⁹
  // (relative to L(1)); powers 0 and 38 meet it within 0.6 % of the peak, and no polynomial of
  // order <= 12 within both the tolerance and the conditioning limit does.
  const Luminaire luminaire = placeLuminaire(
      {kExampleLuminaires / "narrow-downlight.ies", Vec3::Zero(), {}, 1.0, LuminaireModel::Area});
  const LuminaireOpening& opening = *luminaire.opening;
  EXPECT_FALSE(opening.subdivided());
  const photometry::LuminanceFit& fit = opening.fit;
  ASSERT_EQ(fit.order(), 38);
  for (int k = 1; k < 38; ++k) EXPECT_EQ(fit.coefficients[k], 0.0) << "k = " << k;
  EXPECT_GT(fit.coefficients[0], 0.0);
  EXPECT_GT(fit.coefficients[38], 0.0);
  EXPECT_LE(fit.peakRelativeError, photometry::kLuminanceFitTolerance);
}

TEST(AreaModelFit, IsExactForAPolynomialLuminance) {
  TempDir dir("luminaire-area");
  // L = c (1 + 2 sin² φ) = c (3 − 2 cos² φ): I = A cos φ L, an order-2 fit.
  const double area = 0.2 * 0.1, c = 5000.0;
  const auto file = writeSymmetricIes(dir, "batwing.ies", 0.2, 0.1, [&](double gammaDeg) {
    const double g = std::cos(gammaDeg * kPi / 180);
    return gammaDeg <= 90 ? std::max(0.0, area * g * c * (3 - 2 * g * g)) : 0.0;
  });
  const Luminaire luminaire = placeLuminaire({file, Vec3::Zero(), {}, 1.0, LuminaireModel::Area});
  const photometry::LuminanceFit& fit = luminaire.opening->fit;
  ASSERT_EQ(fit.order(), 2);
  EXPECT_NEAR(fit.coefficients[0], 3 * c, 1e-9 * c);
  EXPECT_NEAR(fit.coefficients[1], 0.0, 1e-9 * c);
  EXPECT_NEAR(fit.coefficients[2], -2 * c, 1e-9 * c);
  EXPECT_LT(fit.peakRelativeError, 1e-12);
}

TEST(AreaModelFit, ABeamTooNarrowForTheFitFallsBackToPointSourcesOverTheOpening) {
  TempDir dir("luminaire-area");
  // I = I0 cos^400 γ: a 7° beam (half value at 3.4°) from a 0.12 × 0.06 m opening.
  const auto file = writeSymmetricIes(dir, "pencil.ies", 0.12, 0.06, [](double gammaDeg) {
    return gammaDeg < 90 ? kI0 * std::pow(std::cos(gammaDeg * kPi / 180), 400) : 0.0;
  });
  const Luminaire luminaire =
      placeLuminaire({file, Vec3::Zero(), kTurned, 1.0, LuminaireModel::Area});
  ASSERT_TRUE(luminaire.opening.has_value());
  const LuminaireOpening& opening = *luminaire.opening;
  EXPECT_GT(opening.fit.peakRelativeError, photometry::kLuminanceFitTolerance);
  ASSERT_TRUE(opening.subdivided());
  EXPECT_EQ(opening.partsAlongLength, 3);  // cells of 4 cm × 3 cm
  EXPECT_EQ(opening.partsAlongWidth, 2);
  std::printf("  pencil beam: best fit order %d, error %.3f of the peak: %d x %d cells\n",
              opening.fit.order(), opening.fit.peakRelativeError, opening.partsAlongLength,
              opening.partsAlongWidth);
  // Each cell is the point model of 1/6 of the table at the cell's centre.
  Scene area, cells;
  area.luminaires.push_back(luminaire);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 3; ++i) {
      Luminaire cell = placeLuminaire({file, Vec3::Zero(), kTurned, 1.0, LuminaireModel::Point});
      cell.intensityScale /= 6;
      cell.instances.front().position = aimRotation(kTurned) * opening.partCentre(i, j);
      cells.luminaires.push_back(cell);
    }
  const Vec3 axis = aimRotation(kTurned) * -Vec3::UnitZ();
  std::vector<SamplePoint> points;
  for (double r : {1.0, 3.0})
    for (double off : {-0.05, 0.0, 0.02})
      points.push_back({r * axis + Vec3(off, -off, 0.0), -axis, -1});
  const std::vector<double> a = referenceE(area, points), c = referenceE(cells, points);
  for (std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_GT(c[i], 0.0);
    EXPECT_NEAR(a[i], c[i], 1e-12 * c[i]);
  }
}

TEST(AreaModelFit, AnAsymmetricDistributionFallsBack) {
  // The batwing's C0-C180 and C90-C270 planes differ; the fit is the rotational mean.
  const Luminaire luminaire = placeLuminaire(
      {kExampleLuminaires / "batwing.ldt", Vec3::Zero(), {}, 1.0, LuminaireModel::Area});
  const LuminaireOpening& opening = *luminaire.opening;
  EXPECT_GT(opening.fit.peakRelativeError, photometry::kLuminanceFitTolerance);
  EXPECT_TRUE(opening.subdivided());
  EXPECT_EQ(opening.partsAlongLength, 16);  // 1.2 m: at most 16 cells
  EXPECT_EQ(opening.partsAlongWidth, 3);    // 0.15 m: 5 cm cells
}

TEST(AreaModelOutline, ADiskIsTheRegularPolygonOfTheSameArea) {
  photometry::LuminousOpening disk;
  disk.shape = photometry::OpeningShape::Disk;
  disk.lengthM = disk.widthM = 0.2;
  const ConvexPolygon polygon(photometry::flatOutline(disk));
  EXPECT_EQ(polygon.size(), photometry::kRoundOpeningSides);
  EXPECT_NEAR(polygon.area(), kPi * 0.01, 1e-15);
  EXPECT_NEAR(polygon.normal().z(), -1.0, 1e-15);
}

// ---- the area model in the kernel (float) against the host reference (double)

// The kernel's E with `options`' paths.
std::vector<double> kernelE(const Scene& scene, std::span<const SamplePoint> points,
                            const EngineOptions& options) {
  IlluminanceEngine engine(cpuDevice(), scene, options);
  return engine.illuminance(points);
}

struct KernelPath {
  const char* name;
  EngineOptions options;
};

const KernelPath kKernelPaths[] = {
    {"eight lanes", EngineOptions{}},
    {"scalar", EngineOptions{true, true, false}},
    {"plain", EngineOptions{false, true, false}},
};

// Whether `point` sees `luminaire`'s opening clearly: every vertex more than kClearSine above the
// point's horizon (the sine of the angle from it), and the point in front of the opening's plane
// by more than kClearPlaneSine. Low on the point's horizon the contour's terms cancel to a small
// E and float rounding of each term, the Lambertian source's as much as the polynomial's, is a
// larger part of it (the kernel's Lambertian `rect` errs there by up to 1.8e-4 of E unoccluded
// against the exact reference). Near the opening's plane the kernel takes its terms in that
// plane (kernels/planar_term.cl); only a point within rounding of the plane itself, where E is
// 0 but for the rounding, is left out.
constexpr double kClearSine = 0.1;
constexpr double kClearPlaneSine = 0.01;
bool seenClearly(const Luminaire& luminaire, const SamplePoint& point) {
  const ConvexPolygon polygon = placedOpening(*luminaire.opening, luminaire.instances.front());
  for (const Vec3& v : polygon.vertices()) {
    const Vec3 d = v - point.position;
    if (point.normal.dot(d) <= kClearSine * d.norm()) return false;
    if (polygon.normal().dot(-d) <= kClearPlaneSine * d.norm()) return false;
  }
  return true;
}

struct KernelAgreement {
  double clear = 0.0;  // largest |kernel − reference| / E unoccluded, points that see it clearly
  double peak = 0.0;   // largest |kernel − reference| / the largest E unoccluded, every point
};

// The kernel's agreement with the reference: relative to each point's unoccluded E where the
// point sees the opening clearly (the kernel's relative tolerance, as every path is held to the
// exact reference: docs/method.md), relative to the largest unoccluded E of the grid everywhere.
constexpr double kAgreementClear = Tolerance::kKernelRelative;
constexpr double kAgreementPeak = 5e-6;

KernelAgreement agreement(const Scene& scene, const std::vector<SamplePoint>& points,
                          const std::vector<double>& kernel, const std::string& label) {
  Scene open;
  open.luminaires = scene.luminaires;
  const std::vector<double> reference = referenceE(scene, points);
  const std::vector<double> unoccluded = referenceE(open, points);
  const double peak = *std::max_element(unoccluded.begin(), unoccluded.end());
  // Cells are point sources with hard shadows: a point on a cell's shadow boundary may see it in
  // double and not in float (the kernel's tolerance), so partly shaded points are left out.
  const bool cells = scene.luminaires.front().opening->subdivided();
  KernelAgreement a;
  int clear = 0, shadedClear = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (cells && reference[i] > 0.0 && reference[i] < unoccluded[i] * (1 - 1e-9)) continue;
    const double error = std::abs(kernel[i] - reference[i]);
    a.peak = std::max(a.peak, error / peak);
    EXPECT_LE(error, kAgreementPeak * peak) << label << " at " << points[i].position.transpose();
    if (!seenClearly(scene.luminaires.front(), points[i])) continue;
    ++clear;
    if (reference[i] < 0.999 * unoccluded[i]) ++shadedClear;
    a.clear = std::max(a.clear, error / unoccluded[i]);
    EXPECT_LE(error, kAgreementClear * unoccluded[i])
        << label << " at " << points[i].position.transpose();
  }
  EXPECT_GT(clear, 1000) << label;
  if (!cells) {
    EXPECT_GT(shadedClear, 100) << label;  // occluded points among them
  }
  return a;
}

// Luminances of the fitted form: I = A cos γ L(cos γ), L a polynomial (order 2), and one whose
// fit needs a higher order.
double quadraticLuminanceCandela(double gammaDeg) {
  const double g = std::cos(gammaDeg * kPi / 180);
  return gammaDeg <= 90 ? std::max(0.0, kI0 * g * (3 - 2 * g * g) / 3) : 0.0;
}
double peakedLuminanceCandela(double gammaDeg) {
  const double g = std::cos(gammaDeg * kPi / 180);
  return gammaDeg <= 90 ? std::max(0.0, kI0 * g * (0.25 + 0.75 * std::pow(g, 9))) : 0.0;
}

// A narrow downlight, L = c (0.03 + 0.97 cos³⁹φ) (half the peak intensity at 10.6°), from a disk
// of `diameterM` (an IES file of the kind data/luminaires/narrow-downlight.ies is).
std::filesystem::path writeNarrowDownlight(const TempDir& dir, double diameterM) {
  tf::IesSpec spec;
  spec.vertical = tf::steps(0, 180, 1);
  spec.horizontal = {0};
  spec.width = -diameterM;  // LM-63: a disk of diameter −width
  spec.candela = [](double, double gammaDeg) {
    const double g = std::cos(gammaDeg * kPi / 180);
    return gammaDeg < 90 ? kI0 * g * (0.03 + 0.97 * std::pow(g, 39)) : 0.0;
  };
  const std::string name = "downlight-" + std::to_string(std::lround(diameterM * 1000)) + "mm.ies";
  return writeFile(dir.path(), name, tf::iesText(spec));
}

TEST(AreaModelKernel, MatchesTheReferenceOnEveryPathOccludedOrNot) {
  TempDir dir("luminaire-area");
  struct Case {
    const char* name;
    std::filesystem::path file;
  };
  const Case cases[] = {
      {"quadratic", writeSymmetricIes(dir, "quadratic.ies", 0.6, 0.3, quadraticLuminanceCandela)},
      {"peaked", writeSymmetricIes(dir, "peaked.ies", 0.6, 0.3, peakedLuminanceCandela)},
      {"lambertian-panel", kExampleLuminaires / "lambertian-panel.ldt"},
      {"narrow downlight, 0.15 m disk (powers 0 and 38)", writeNarrowDownlight(dir, 0.15)},
      {"batwing (cells)", kExampleLuminaires / "batwing.ldt"},
  };
  const std::vector<SamplePoint> points = roomPoints();
  for (const Case& c : cases) {
    Scene scene = roomSolids();
    scene.luminaires.push_back(
        placeLuminaire({c.file, Vec3(1.0, 0.5, 3.0), kTurned, 0.9, LuminaireModel::Area}));
    const LuminaireOpening& opening = *scene.luminaires.front().opening;
    for (const KernelPath& path : kKernelPaths) {
      const std::string label = std::string(c.name) + ", " + path.name;
      const KernelAgreement a =
          agreement(scene, points, kernelE(scene, points, path.options), label);
      std::printf(
          "  %s (order %d, cells %d x %d), %s path: largest |kernel − reference| %.2e of "
          "E unoccluded where seen clearly, %.2e of the peak\n",
          c.name, opening.fit.order(), opening.partsAlongLength, opening.partsAlongWidth, path.name,
          a.clear, a.peak);
    }
  }
}

TEST(AreaModelKernel, AHighOrderFitMatchesTheReference) {
  // A luminance the fit meets within its conditioning limit only at order 12, so that every term
  // of the recurrence counts: L ∝ 1 + cos¹²φ.
  TempDir dir("luminaire-area");
  const auto file = writeSymmetricIes(dir, "spot.ies", 0.6, 0.3, [](double gammaDeg) {
    const double g = std::cos(gammaDeg * kPi / 180);
    return gammaDeg <= 90 ? std::max(0.0, kI0 * g * (1 + std::pow(g, 12)) / 2) : 0.0;
  });
  Scene scene = roomSolids();
  scene.luminaires.push_back(
      placeLuminaire({file, Vec3(1.0, 0.5, 3.0), kTurned, 1.0, LuminaireModel::Area}));
  const LuminaireOpening& opening = *scene.luminaires.front().opening;
  ASSERT_FALSE(opening.subdivided());
  EXPECT_GE(opening.fit.order(), 10);
  EXPECT_LE(opening.fit.conditioning(), photometry::kLuminanceConditioningLimit);
  const std::vector<SamplePoint> points = roomPoints();
  const KernelAgreement a =
      agreement(scene, points, kernelE(scene, points, EngineOptions{}), "high order");
  std::printf(
      "  order %d: largest |kernel − reference| %.2e of E unoccluded where seen "
      "clearly, %.2e of the peak\n",
      opening.fit.order(), a.clear, a.peak);
}

// E of `luminaire`'s fitted luminance over its whole opening at `point` by quadrature in double:
// the opening's polygon as triangles from its centroid, each the image of the unit square
// (s, t) ↦ v0 + s (v1 − v0) + s t (v2 − v1), 5 × 5 Gauss–Legendre points;
// E = scale ∫ L(g) g (n·ω) / r² dA, g = −N·ω.
double quadratureE(const Luminaire& luminaire, const SamplePoint& point) {
  const ConvexPolygon polygon = placedOpening(*luminaire.opening, luminaire.instances.front());
  const std::vector<Vec3>& v = polygon.vertices();
  Vec3 centroid = Vec3::Zero();
  for (const Vec3& x : v) centroid += x / static_cast<double>(v.size());
  const Vec3 emission = polygon.normal();
  const photometry::LuminanceFit& fit = luminaire.opening->fit;
  double sum = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3 &v1 = v[i], &v2 = v[(i + 1) % v.size()];
    const double twiceArea = (v1 - centroid).cross(v2 - v1).norm();
    for (int a = 0; a < 5; ++a)
      for (int b = 0; b < 5; ++b) {
        const double s = 0.5 * (1 + kGauss5Nodes[a]), t = 0.5 * (1 + kGauss5Nodes[b]);
        const Vec3 x = centroid + s * (v1 - centroid) + s * t * (v2 - v1);
        const Vec3 d = x - point.position;
        const double r2 = d.squaredNorm();
        const Vec3 omega = d / std::sqrt(r2);
        const double g = -emission.dot(omega), h = point.normal.dot(omega);
        if (g <= 0.0 || h <= 0.0) continue;
        sum += 0.25 * kGauss5Weights[a] * kGauss5Weights[b] * s * twiceArea * fit.luminance(g) * g *
               h / r2;
      }
  }
  return luminaire.intensityScale * sum;
}

TEST(AreaModelKernel, NarrowBeamsMatchQuadratureOverTheOpening) {
  // Nonnegative fits beyond the polynomials' order: the downlight's powers 0 and 38 (0.6 % of
  // the peak), the spot's 0 and 24. The kernel integrates each arc's share of the high power in
  // the azimuth form (kernels/luminance_moments.cl); the reference is quadrature of the same
  // fitted luminance over the opening, unoccluded. The sanitizer build takes every third point.
  TempDir dir("luminaire-area");
  struct Case {
    const char* name;
    std::filesystem::path file;
  };
  const Case cases[] = {
      {"narrow downlight, 0.15 m disk", writeNarrowDownlight(dir, 0.15)},
      // The example file's opening (data/luminaires/narrow-downlight.ies): 3 m away, each arc's
      // term is of the order of 0.08 m / 3 m rad and the terms cancel to E, of its square.
      {"narrow downlight, 0.08 m disk", writeNarrowDownlight(dir, 0.08)},
      {"spot 1 + cos^24, 0.3 x 0.3 m", writeSymmetricIes(dir, "spot.ies", 0.3, 0.3, spotCandela)},
  };
  std::vector<SamplePoint> points;
  const std::vector<SamplePoint> room = roomPoints();
  for (std::size_t i = 0; i < room.size(); i += kSanitizedBuild ? 3 : 1) points.push_back(room[i]);
  for (const Case& c : cases) {
    Scene scene;
    scene.luminaires.push_back(
        placeLuminaire({c.file, Vec3(1.0, 0.5, 3.0), kTurned, 0.9, LuminaireModel::Area}));
    const Luminaire& luminaire = scene.luminaires.front();
    ASSERT_FALSE(luminaire.opening->subdivided()) << c.name;
    const photometry::LuminanceFit& fit = luminaire.opening->fit;
    EXPECT_GT(fit.order(), photometry::kLuminanceFitMaxOrder) << c.name;
    EXPECT_LE(fit.peakRelativeError, photometry::kLuminanceFitTolerance) << c.name;
    std::vector<double> quadrature(points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      quadrature[i] = quadratureE(luminaire, points[i]);
    for (const KernelPath& path : kKernelPaths) {
      const std::vector<double> kernel = kernelE(scene, points, path.options);
      double worst = 0.0;
      int clear = 0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        if (!seenClearly(luminaire, points[i])) continue;
        ++clear;
        const double error = std::abs(kernel[i] - quadrature[i]);
        worst = std::max(worst, error / quadrature[i]);
        EXPECT_LE(error, kAgreementClear * quadrature[i])
            << c.name << ", " << path.name << " at " << points[i].position.transpose();
      }
      EXPECT_GT(clear, kSanitizedBuild ? 300 : 1000) << c.name;
      std::printf(
          "  %s (power %d, fit error %.2e of the peak), %s path: largest |kernel − quadrature| "
          "%.2e of E where seen clearly (%d points)\n",
          c.name, fit.order(), fit.peakRelativeError, path.name, worst, clear);
    }
  }
}

// The opening as the room's luminaire has it, and a 0.1 × 0.05 m one, whose largest vertex offset
// is below 0.1 of its distance from most points, so that both take their unoccluded terms relative
// to a vertex (kernels/lambert.cl, PN_SMALL_FACE).
TEST(AreaModelKernel, ALambertianFileEqualsTheKernelsRectSourceOfTheSameFlux) {
  TempDir dir("luminaire-area");
  for (const auto& [length, width] : {std::pair{0.6, 0.3}, std::pair{0.1, 0.05}}) {
    const Scene area = roomWithLambertianLuminaire(dir, length, width);
    const Luminaire& luminaire = area.luminaires.front();
    ASSERT_EQ(luminaire.opening->fit.order(), 0);
    const ConvexPolygon polygon = placedOpening(*luminaire.opening, luminaire.instances.front());
    Scene rect = roomSolids();
    rect.sources.push_back(areaSource(polygon.vertices(), kPi * kI0 / (kPi * polygon.area())));
    const std::vector<SamplePoint> points = roomPoints();
    for (const KernelPath& path : kKernelPaths) {
      const std::vector<double> fromArea = kernelE(area, points, path.options);
      const std::vector<double> fromRect = kernelE(rect, points, path.options);
      double worst = 0.0;
      int lit = 0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        if (fromRect[i] == 0.0) {
          EXPECT_EQ(fromArea[i], 0.0) << path.name << " at " << points[i].position.transpose();
          continue;
        }
        ++lit;
        worst = std::max(worst, std::abs(fromArea[i] / fromRect[i] - 1));
        EXPECT_NEAR(fromArea[i], fromRect[i], 1e-6 * fromRect[i])
            << length << " x " << width << " m, " << path.name << " at "
            << points[i].position.transpose();
      }
      EXPECT_GT(lit, 1000);
      std::printf("  %.2f x %.2f m opening, %s path: largest |area / rect − 1| %.2e\n", length,
                  width, path.name, worst);
    }
  }
}

// Small openings past the table: the 80 mm narrow downlight (the example file's opening, powers 0
// and 38) and a 0.1 × 0.05 m Lambertian one, seen from the floor around the table's shadow, where
// the penumbra is 0.07 to 0.1 m wide. Each arc's term is of the order of the opening's angular
// size and the terms cancel to E, of its square: the penumbra paths take them relative to the
// opening's reference vertex where it is small against its distance (kernels/contour.cl,
// PnPieceForm), as the unoccluded path does. Every path is held to `bound` of the point's
// unoccluded E against the reference (closed forms in double over the visible opening). Measured
// on every path: the downlight 9.1e-6, whose high power's parts of each arc are still taken from
// the arc alone (7.3e-6 at points the table does not shade, on the unoccluded path); the
// Lambertian opening 2.3e-6, the rounding of the contour's ends' directions (the table's
// vertices from the point, the side planes' crossings: DistantSource's small panel past a table
// says why). With each piece's term taken alone: 1.25e-5 and 5.2e-6. The sanitizer build takes
// every third point.

TEST(AreaModelKernel, SmallOpeningsPastTheTableMatchTheReferenceOnEveryPath) {
  TempDir dir("luminaire-area");
  struct Case {
    const char* name;
    std::filesystem::path file;
    double bound;  // of E unoccluded
  };
  const Case cases[] = {
      {"narrow downlight, 0.08 m disk", writeNarrowDownlight(dir, 0.08), 1.2e-5},
      {"Lambertian, 0.1 x 0.05 m",
       writeSymmetricIes(dir, "lambertian-100mm.ies", 0.1, 0.05, lambertianCandela), 3e-6},
  };
  std::vector<SamplePoint> points;
  int index = 0;
  for (double x = 0.1; x < 1.8; x += 0.035)
    for (double y = -0.2; y < 1.4; y += 0.035)
      if (index++ % (kSanitizedBuild ? 3 : 1) == 0)
        points.push_back({Vec3(x, y, 0), Vec3::UnitZ(), -1});
  for (const Case& c : cases) {
    Scene scene = roomSolids();
    scene.luminaires.push_back(
        placeLuminaire({c.file, Vec3(1.0, 0.5, 3.0), kTurned, 1.0, LuminaireModel::Area}));
    Scene open;
    open.luminaires = scene.luminaires;
    ASSERT_FALSE(scene.luminaires.front().opening->subdivided()) << c.name;
    const std::vector<double> reference = referenceE(scene, points);
    const std::vector<double> unoccluded = referenceE(open, points);
    int penumbra = 0;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (reference[i] > 1e-3 * unoccluded[i] && reference[i] < (1 - 1e-3) * unoccluded[i])
        ++penumbra;
    EXPECT_GT(penumbra, kSanitizedBuild ? 30 : 100) << c.name;
    for (const KernelPath& path : kKernelPaths) {
      const std::vector<double> kernel = kernelE(scene, points, path.options);
      double worst = 0.0, worstShaded = 0.0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        ASSERT_GT(unoccluded[i], 0.0) << points[i].position.transpose();
        const double error = std::abs(kernel[i] - reference[i]) / unoccluded[i];
        worst = std::max(worst, error);
        if (reference[i] < (1 - 1e-3) * unoccluded[i]) worstShaded = std::max(worstShaded, error);
        EXPECT_LE(error, c.bound) << c.name << ", " << path.name << " at "
                                  << points[i].position.transpose() << ": E = " << kernel[i]
                                  << " lx, reference " << reference[i] << " lx";
      }
      std::printf(
          "  %s, %s path: %zu points (%d in the penumbra), largest |kernel − reference| %.2e of "
          "E unoccluded (%.2e where shaded)\n",
          c.name, path.name, points.size(), penumbra, worst, worstShaded);
    }
  }
}

}  // namespace
}  // namespace penumbra
