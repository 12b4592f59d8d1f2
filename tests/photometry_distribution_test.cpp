// The distribution from a file: symmetries expanded to the sphere, the same distribution written
// in every symmetry and both formats, bilinear interpolation, the frames of types A, B and C and
// the zonal flux against its closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "photometry/ies_reader.hpp"
#include "photometry/ldt_reader.hpp"
#include "photometry/light_distribution.hpp"
#include "photometry/zonal_flux.hpp"
#include "photometry_files.hpp"

namespace {

using namespace penumbra::photometry;
using penumbra::Vec3;
using testfiles::IesSpec;
using testfiles::LdtSpec;
using testfiles::steps;

constexpr double kPi = std::numbers::pi;
constexpr double kI0 = 1000;  // cd

// An IES type C file of `intensity` with horizontal angles `h` (a symmetry), γ every 5°.
LightDistribution iesDistribution(const std::vector<double>& h,
                                  const testfiles::Intensity& intensity,
                                  std::string version = "IESNA:LM-63-2002") {
  IesSpec spec;
  spec.versionLine = version;
  spec.vertical = steps(0, 180, 5);
  spec.horizontal = h;
  spec.candela = intensity;
  return LightDistribution(parseIes(testfiles::iesText(spec), "test.ies"));
}

// A EULUMDAT file of `intensity` (cd/klm for 1000 lm, so cd) with Isym `isym`, every 15° in C.
LightDistribution ldtDistribution(int isym, const testfiles::Intensity& intensity) {
  LdtSpec spec;
  spec.isym = isym;
  spec.cdPerKlm = intensity;
  return LightDistribution(parseLdt(testfiles::ldtText(spec), "test.ldt"));
}

// Directions spread over the sphere, nodes and poles among them.
std::vector<Vec3> directions() {
  std::vector<Vec3> out{{0, 0, -1}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (int i = 0; i < 400; ++i) out.push_back(Vec3(normal(random), normal(random), normal(random)));
  return out;
}

void expectSameEverywhere(const LightDistribution& a, const LightDistribution& b,
                          const std::string& what) {
  for (const Vec3& d : directions()) {
    EXPECT_NEAR(a.intensity(d), b.intensity(d), 1e-12 * kI0) << what << " at " << d.transpose();
  }
}

// Bilinear interpolation of I0 cos γ in γ alone (a distribution with no C dependence), computed
// here from the node values: the value intensity() must give.
double lambertInterpolated(double gammaDeg) {
  if (gammaDeg >= 90) return 0;
  const double k = std::floor(gammaDeg / 5);
  const double s = gammaDeg / 5 - k;
  return (1 - s) * testfiles::lambertian(kI0, 5 * k) + s * testfiles::lambertian(kI0, 5 * (k + 1));
}

TEST(LightDistribution, LambertianIsTheSameInEverySymmetryAndBothFormats) {
  const auto lambert = [](double, double gamma) { return testfiles::lambertian(kI0, gamma); };
  const LightDistribution reference = iesDistribution({0}, lambert);
  const std::vector<std::pair<std::string, LightDistribution>> variants = {
      {"IES 0-90", iesDistribution(steps(0, 90, 15), lambert)},
      {"IES 0-180", iesDistribution(steps(0, 180, 15), lambert)},
      {"IES 0-360", iesDistribution(steps(0, 360, 15), lambert)},
      {"IES 1995 90-270", iesDistribution(steps(90, 270, 15), lambert, "IESNA:LM-63-1995")},
      {"LDT Isym 0", ldtDistribution(0, lambert)},
      {"LDT Isym 1", ldtDistribution(1, lambert)},
      {"LDT Isym 2", ldtDistribution(2, lambert)},
      {"LDT Isym 3", ldtDistribution(3, lambert)},
      {"LDT Isym 4", ldtDistribution(4, lambert)},
  };
  for (const auto& [name, distribution] : variants)
    expectSameEverywhere(reference, distribution, name);
  for (const Vec3& d : directions()) {
    const double gamma = std::atan2(std::hypot(d.x(), d.y()), -d.z()) * 180 / kPi;
    EXPECT_NEAR(reference.intensity(d), lambertInterpolated(gamma), 1e-12 * kI0) << d.transpose();
  }
}

TEST(LightDistribution, MirroredPlanesMatchTheFullTable) {
  // Symmetric about C0-C180 and C90-C270: every symmetry can hold it.
  const auto both = [](double c, double gamma) {
    return testfiles::lambertian(kI0, gamma) * (1 + 0.5 * std::cos(2 * c * kPi / 180));
  };
  const LightDistribution full = iesDistribution(steps(0, 360, 15), both);
  expectSameEverywhere(full, iesDistribution(steps(0, 90, 15), both), "IES 0-90");
  expectSameEverywhere(full, iesDistribution(steps(0, 180, 15), both), "IES 0-180");
  expectSameEverywhere(full, iesDistribution(steps(90, 270, 15), both, "IESNA:LM-63-1995"),
                       "IES 90-270");
  for (int isym : {0, 2, 3, 4}) {
    expectSameEverywhere(full, ldtDistribution(isym, both), "Isym " + std::to_string(isym));
  }
  // Symmetric about C0-C180 only.
  const auto c0 = [](double c, double gamma) {
    return testfiles::lambertian(kI0, gamma) * (1 + 0.5 * std::cos(c * kPi / 180));
  };
  const LightDistribution fullC0 = iesDistribution(steps(0, 360, 15), c0);
  expectSameEverywhere(fullC0, iesDistribution(steps(0, 180, 15), c0), "IES 0-180");
  expectSameEverywhere(fullC0, ldtDistribution(2, c0), "Isym 2");
  EXPECT_NEAR(fullC0.intensity(TableAngles{180, 30}), testfiles::lambertian(kI0, 30) * 0.5, 1e-9);
  // Symmetric about C90-C270 only.
  const auto c90 = [](double c, double gamma) {
    return testfiles::lambertian(kI0, gamma) * (1 + 0.5 * std::sin(c * kPi / 180));
  };
  const LightDistribution fullC90 = iesDistribution(steps(0, 360, 15), c90);
  expectSameEverywhere(fullC90, iesDistribution(steps(90, 270, 15), c90, "IESNA:LM-63-1995"),
                       "IES 90-270");
  expectSameEverywhere(fullC90, ldtDistribution(3, c90), "Isym 3");
  EXPECT_NEAR(fullC90.intensity(TableAngles{270, 30}), testfiles::lambertian(kI0, 30) * 0.5, 1e-9);
}

TEST(LightDistribution, NodesAreExactAndMidpointsAreTheBilinearAverage) {
  const auto uneven = [](double c, double gamma) {
    return 100 + 7 * c + 3 * gamma + 0.01 * c * gamma + 5 * std::sin(c * gamma);
  };
  IesSpec spec;
  spec.vertical = {0, 5, 12.5, 30, 60, 90, 135, 180};
  spec.horizontal = {0, 20, 45, 90, 150, 200, 270, 300, 360};
  spec.candela = uneven;
  const PhotometricData data = parseIes(testfiles::iesText(spec), "uneven.ies");
  const LightDistribution d(data);
  for (std::size_t h = 0; h + 1 < spec.horizontal.size(); ++h) {
    for (std::size_t v = 0; v < spec.vertical.size(); ++v) {
      const double c = spec.horizontal[h], g = spec.vertical[v];
      EXPECT_EQ(d.intensity(TableAngles{c, g}), uneven(c, g)) << c << " " << g;
      // Through a direction the angles round-trip to within an ulp or so; at the poles every C
      // is the same direction (anglesOf gives C = 0), and this table is not the same there.
      if (g == 0 || g == 180) continue;
      EXPECT_NEAR(d.intensity(directionOf(PhotometricType::C, {c, g})), uneven(c, g),
                  1e-9 * uneven(c, g));
      // The 360° row is C0 again: the cell from 300° to 360° is checked below.
      if (v + 1 == spec.vertical.size() || h + 2 == spec.horizontal.size()) continue;
      const double c1 = spec.horizontal[h + 1], g1 = spec.vertical[v + 1];
      const double average = (uneven(c, g) + uneven(c1, g) + uneven(c, g1) + uneven(c1, g1)) / 4;
      EXPECT_NEAR(d.intensity(TableAngles{(c + c1) / 2, (g + g1) / 2}), average, 1e-12 * average);
    }
  }
  // The last plane (300°) interpolates towards 360° = C0.
  const double wrapped = (uneven(300, 30) + uneven(0, 30)) / 2;
  EXPECT_NEAR(d.intensity(TableAngles{330, 30}), wrapped, 1e-12 * wrapped);
}

TEST(LightDistribution, ZeroOutsideTheMeasuredRange) {
  IesSpec spec;
  spec.vertical = steps(0, 90, 10);
  spec.horizontal = {0};
  spec.candela = [](double, double) { return 50.0; };
  const LightDistribution d(parseIes(testfiles::iesText(spec), "down.ies"));
  EXPECT_EQ(d.intensity(Vec3(0, 0, -1)), 50.0);
  EXPECT_EQ(d.intensity(Vec3(1, 0, 0)), 50.0);
  EXPECT_EQ(d.intensity(Vec3(1, 0, 0.01)), 0.0);
  EXPECT_EQ(d.intensity(Vec3(0, 0, 1)), 0.0);
}

TEST(ZonalFlux, LambertianMatchesItsClosedForm) {
  // I0 cos γ every Δ: π I0 (2 - 1/cos(Δ/2)) (docs/photometry.md), whatever the C planes.
  const auto lambert = [](double, double gamma) { return testfiles::lambertian(kI0, gamma); };
  for (double delta : {1.0, 2.5, 5.0, 10.0}) {
    IesSpec spec;
    spec.vertical = steps(0, 180, delta);
    spec.horizontal = steps(0, 90, 15);
    spec.candela = lambert;
    const double zonal = zonalFlux(LightDistribution(parseIes(testfiles::iesText(spec), "l.ies")));
    const double closed = kPi * kI0 * (2 - 1 / std::cos(delta / 2 * kPi / 180));
    EXPECT_NEAR(zonal, closed, 1e-12 * closed) << delta;
    // And the discretisation error against π I0 is -Δ²/8 to leading order.
    const double d = delta * kPi / 180;
    EXPECT_NEAR((zonal - kPi * kI0) / (kPi * kI0), -d * d / 8, 0.01 * d * d);
  }
  for (int isym : {0, 1, 2, 3, 4}) {
    const double zonal = zonalFlux(ldtDistribution(isym, lambert));
    EXPECT_NEAR(zonal, kPi * kI0 * (2 - 1 / std::cos(2.5 * kPi / 180)), 1e-9) << isym;
  }
  // C dependence that averages to zero over the planes leaves the flux as it is.
  const auto both = [](double c, double gamma) {
    return testfiles::lambertian(kI0, gamma) * (1 + 0.5 * std::cos(2 * c * kPi / 180));
  };
  EXPECT_NEAR(zonalFlux(ldtDistribution(4, both)), kPi * kI0 * (2 - 1 / std::cos(2.5 * kPi / 180)),
              1e-9);
}

TEST(ZonalFlux, UniformSphereIsFourPiI0) {
  // A constant intensity integrates to 4π I, exactly for any nodes from 0 to 180°.
  IesSpec spec;
  spec.vertical = {0, 3, 10, 45, 90, 100, 170, 180};
  spec.horizontal = {0, 30, 90};
  spec.candela = [](double, double) { return 10.0; };
  EXPECT_NEAR(zonalFlux(LightDistribution(parseIes(testfiles::iesText(spec), "u.ies"))),
              4 * kPi * 10, 1e-12);
}

TEST(PhotometricFrame, TypeCAxes) {
  const auto d = [](double c, double g) { return directionOf(PhotometricType::C, {c, g}); };
  EXPECT_TRUE(d(0, 0).isApprox(Vec3(0, 0, -1)));
  EXPECT_TRUE(d(0, 90).isApprox(Vec3(1, 0, 0)));
  EXPECT_TRUE(d(90, 90).isApprox(Vec3(0, 1, 0)));
  EXPECT_TRUE(d(180, 90).isApprox(Vec3(-1, 0, 0)));
  EXPECT_TRUE(d(0, 180).isApprox(Vec3(0, 0, 1)));
}

TEST(PhotometricFrame, TypesAAndBAimDownWithTheirPolarAxes) {
  for (auto type : {PhotometricType::A, PhotometricType::B}) {
    EXPECT_TRUE(directionOf(type, {0, 0}).isApprox(Vec3(0, 0, -1)));
    // Positive H turns towards +y, positive V towards +x, in both.
    EXPECT_TRUE(directionOf(type, {90, 0}).isApprox(Vec3(0, 1, 0)));
    EXPECT_TRUE(directionOf(type, {0, 90}).isApprox(Vec3(1, 0, 0)));
  }
  // Type B: polar axis +y, planes turn with V: (H, V) = (30, 60) lies in the plane through +y
  // tilted 60° from -z towards +x.
  const Vec3 b = directionOf(PhotometricType::B, {30, 60});
  EXPECT_NEAR(b.y(), std::sin(30 * kPi / 180), 1e-15);
  EXPECT_NEAR(std::atan2(b.x(), -b.z()), 60 * kPi / 180, 1e-15);
  // Type A: polar axis +x, planes turn with H.
  const Vec3 a = directionOf(PhotometricType::A, {30, 60});
  EXPECT_NEAR(a.x(), std::sin(60 * kPi / 180), 1e-15);
  EXPECT_NEAR(std::atan2(a.y(), -a.z()), 30 * kPi / 180, 1e-15);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-89, 89);
  for (int i = 0; i < 200; ++i) {
    for (auto type : {PhotometricType::A, PhotometricType::B, PhotometricType::C}) {
      TableAngles angles{u(random), u(random)};
      if (type == PhotometricType::C)
        angles = {angles.horizontalDeg + 180, angles.verticalDeg + 90};
      const TableAngles back = anglesOf(type, directionOf(type, angles));
      EXPECT_NEAR(back.horizontalDeg, angles.horizontalDeg, 1e-9);
      EXPECT_NEAR(back.verticalDeg, angles.verticalDeg, 1e-9);
    }
  }
}

// A Lambertian emitter facing -z written as type A or B: I = I0 cos H cos V every Δ over
// -90..90 in both angles. Its zonal flux has the closed form π I0 cos(Δ/2) (docs/photometry.md)
// and its intensity equals type C's at their common nodes.
TEST(ZonalFlux, LambertianInTypesAAndB) {
  for (int type : {2, 3}) {
    for (bool lateral : {false, true}) {
      IesSpec spec;
      spec.type = type;
      spec.vertical = steps(-90, 90, 5);
      spec.horizontal = steps(lateral ? 0 : -90, 90, 5);
      spec.candela = [](double h, double v) {
        return kI0 * std::cos(h * kPi / 180) * std::cos(v * kPi / 180);
      };
      const PhotometricData data = parseIes(testfiles::iesText(spec), "ab.ies");
      EXPECT_EQ(data.symmetry, lateral ? HorizontalSymmetry::Lateral : HorizontalSymmetry::None);
      const LightDistribution d(data);
      EXPECT_NEAR(zonalFlux(d), kPi * kI0 * std::cos(2.5 * kPi / 180), 1e-9) << type << lateral;
      for (double h : steps(-90, 90, 15)) {
        for (double v : steps(-90, 90, 15)) {
          const Vec3 dir = directionOf(data.type, {h, v});
          EXPECT_NEAR(d.intensity(dir), kI0 * -dir.z(), 1e-9 * kI0) << h << " " << v;
        }
      }
      // Behind the luminaire nothing.
      EXPECT_EQ(d.intensity(Vec3(0.1, 0.2, 1)), 0.0);
    }
  }
}

TEST(LightDistribution, PeakIsTheLargestNode) {
  IesSpec spec;
  spec.vertical = steps(0, 90, 10);
  spec.horizontal = steps(0, 180, 30);
  spec.candela = [](double c, double g) { return (c == 60 && g == 30) ? 900.0 : c + g; };
  const LightDistribution d(parseIes(testfiles::iesText(spec), "peak.ies"));
  const PeakIntensity peak = d.peak();
  EXPECT_EQ(peak.candela, 900.0);
  EXPECT_EQ(peak.at.horizontalDeg, 60);
  EXPECT_EQ(peak.at.verticalDeg, 30);
}

}  // namespace
