// The CIE 190 UGR table (docs/glare.md, "The UGR table of a luminaire") against calculations
// written here: the transfer factors against the values CIE 190 publishes, the table against a
// direct summation over the luminaire array with the angles of CIE 117 (C, γ by their arctangent
// formulas) and the flux fractions summed zone by zone, one cell of a Lambertian panel by hand,
// and the swap of crosswise and endwise for a luminaire turned by 90°.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "glare/position_index.hpp"
#include "glare/room_transfer.hpp"
#include "glare/tabular_flux.hpp"
#include "glare/ugr_table.hpp"
#include "photometry/ldt_reader.hpp"
#include "photometry/light_distribution.hpp"
#include "photometry/zonal_flux.hpp"
#include "photometry_files.hpp"

namespace penumbra {
namespace {

using photometry::LightDistribution;
using photometry::PhotometricData;
using photometry::TableAngles;
namespace testfiles = photometry::testfiles;

constexpr double kPi = std::numbers::pi;
double radians(double deg) {
  return deg * kPi / 180.0;
}
double degrees(double rad) {
  return rad * 180.0 / kPi;
}

PhotometricData ldt(const testfiles::LdtSpec& spec) {
  return photometry::parseLdt(testfiles::ldtText(spec), "test.ldt");
}

// I = 300 cd/klm · cos γ · (1 + 0.5 sin(C − turnDeg)) below the horizon: mirror-symmetric about
// the plane C90-C270 turned by `turnDeg`, not about the plane across it, so that crosswise and
// endwise differ. 600 mm x 300 mm luminous area (swapped when turned by 90°), 4000 lm of lamps.
testfiles::LdtSpec asymmetricSpec(double turnDeg) {
  testfiles::LdtSpec spec;
  spec.isym = 0;
  const bool quarter = std::abs(turnDeg) == 90.0;
  spec.areaLength = quarter ? 300 : 600;
  spec.areaWidth = quarter ? 600 : 300;
  spec.lampSets = {testfiles::LdtLampSet{1, 4000, 30}};
  spec.cdPerKlm = [turnDeg](double c, double gamma) {
    return testfiles::lambertian(300.0, gamma) * (1.0 + 0.5 * std::sin(radians(c - turnDeg)));
  };
  return spec;
}

// CIE 190:2010 table 5: F_T,FW, F_T,WW-1, F_T,CW for 0.70/0.50/0.20 and 0.30/0.30/0.20.
struct PublishedTransfer {
  int x, y;
  RoomReflectances reflectances;
  double fw, ww, cw;
};
const PublishedTransfer kPublished[] = {
    {2, 2, {0.7, 0.5, 0.2}, 0.220, 0.422, 0.646},  {2, 2, {0.3, 0.3, 0.2}, 0.157, 0.181, 0.227},
    {4, 8, {0.7, 0.5, 0.2}, 0.115, 0.211, 0.307},  {4, 8, {0.3, 0.3, 0.2}, 0.081, 0.092, 0.114},
    {8, 8, {0.7, 0.5, 0.2}, 0.083, 0.155, 0.215},  {12, 6, {0.7, 0.5, 0.2}, 0.083, 0.153, 0.216},
    {12, 8, {0.7, 0.5, 0.2}, 0.071, 0.133, 0.183}, {12, 8, {0.3, 0.3, 0.2}, 0.049, 0.059, 0.069},
    {4, 3, {0.7, 0.3, 0.2}, 0.142, 0.159, 0.393},  {2, 12, {0.5, 0.3, 0.2}, 0.128, 0.140, 0.276},
};

TEST(UgrTable, TransferFactorsAreThePublishedOnesToTheirLastDigit) {
  for (const PublishedTransfer& p : kPublished) {
    const WallTransfer t = wallTransfer(p.x, p.y, 1.0, p.reflectances);
    const std::string where = std::to_string(p.x) + "H x " + std::to_string(p.y) + "H";
    EXPECT_NEAR(t.fromFloor, p.fw, 0.0005) << where;
    EXPECT_NEAR(t.fromWalls, p.ww, 0.0005) << where;
    EXPECT_NEAR(t.fromCeiling, p.cw, 0.0005) << where;
  }
}

// The whole tabular formula for one room, written out: the luminaires at (T, R) with
// C = atan(T/R) crosswise and 90° − atan(T/R) endwise (CIE 117, 4.5 and 4.6, C0 along the line
// of sight when crosswise; T's sign mirrors C), γ = atan(√(R² + T²)/H), L = I/(A cos γ),
// ω = A cos γ / r²; the zones' flux from the C-average over the file's 24 planes (trapezoids of
// a piecewise-linear function: exact).
struct Direct {
  double crosswise = 0.0, endwise = 0.0;
  double background[5] = {};
};

Direct directTable(const PhotometricData& data, const LightDistribution& d, double area,
                   const StandardRoom& room, double spacingRatio) {
  const double h = 2.0, s = spacingRatio * h, x = room.acrossH * h, y = room.alongH * h;
  Direct out;
  const int nx = static_cast<int>(std::lround(x / s)), ny = static_cast<int>(std::lround(y / s));
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      const double t = -x / 2 + (i + 0.5) * s, r = (j + 0.5) * s;
      const std::optional<double> p = guthPositionIndex({r, h, std::abs(t)});
      if (!p) continue;
      const double gamma = degrees(std::atan(std::hypot(r, t) / h));
      const double c = degrees(std::atan2(t, r));
      const double cross = d.intensity(TableAngles{360.0 - c, gamma});
      const double end = d.intensity(TableAngles{270.0 - c, gamma});
      const double projected = area * std::cos(radians(gamma));
      const double omega = projected / (r * r + t * t + h * h);
      out.crosswise += std::pow(cross / projected, 2) * omega / (*p * *p);
      out.endwise += std::pow(end / projected, 2) * omega / (*p * *p);
    }
  }
  // Zones of 10°: C-average at the middle, times 2π(cos γ1 − cos γ2).
  double zone[18];
  for (int z = 0; z < 18; ++z) {
    double average = 0.0;
    for (double plane : data.horizontalAnglesDeg)
      average += d.intensity(TableAngles{plane, 10.0 * z + 5});
    average /= static_cast<double>(data.horizontalAnglesDeg.size());
    zone[z] = average * 2 * kPi * (std::cos(radians(10.0 * z)) - std::cos(radians(10.0 * z + 10)));
  }
  double down = 0, up = 0;
  for (int z = 0; z < 9; ++z) down += zone[z];
  for (int z = 9; z < 18; ++z) up += zone[z];
  const double partial1 =
      (std::cos(radians(40)) - 0.75) / (std::cos(radians(40)) - std::cos(radians(50)));
  const double partial3 =
      (std::cos(radians(70)) - 0.25) / (std::cos(radians(70)) - std::cos(radians(80)));
  const double cones[4] = {
      zone[0] + zone[1] + zone[2] + zone[3] + partial1 * zone[4],
      zone[0] + zone[1] + zone[2] + zone[3] + zone[4] + zone[5],
      zone[0] + zone[1] + zone[2] + zone[3] + zone[4] + zone[5] + zone[6] + partial3 * zone[7],
      down};
  const double k = x * y / (h * (x + y));
  const GeometricMultipliers f = *geometricMultipliers(k);
  const double flux = down + up;
  const double toFloor =
      (f.f[0] * cones[0] + f.f[1] * cones[1] + f.f[2] * cones[2] + f.f[3] * cones[3]) / flux;
  const double toWalls = down / flux - toFloor, toCeiling = up / flux;
  for (int set = 0; set < 5; ++set) {
    const WallTransfer ft = wallTransfer(x, y, h, kStandardReflectances[set]);
    out.background[set] =
        nx * ny * flux / (2 * h * (x + y)) *
        (toFloor * ft.fromFloor + toWalls * ft.fromWalls + toCeiling * ft.fromCeiling) / kPi;
  }
  return out;
}

TEST(UgrTable, EveryCellIsTheTabularFormulaSummedDirectly) {
  const PhotometricData data = ldt(asymmetricSpec(0.0));
  const LightDistribution distribution(data);
  const TabularLuminaire luminaire = tabularLuminaire(distribution, data.opening);
  ASSERT_NEAR(luminaire.areaM2, 0.18, 1e-12);
  for (double spacing : {0.25, 1.0}) {
    const UgrTable table = computeUgrTable(luminaire, UgrTableSettings{spacing, 2.0});
    ASSERT_EQ(table.rows.size(), kStandardRooms.size());
    for (const UgrTableRow& row : table.rows) {
      const Direct direct = directTable(data, distribution, 0.18, row.room, spacing);
      for (int set = 0; set < 5; ++set) {
        const std::string where = std::to_string(row.room.acrossH) + "H x " +
                                  std::to_string(row.room.alongH) + "H, S/H " +
                                  std::to_string(spacing) + ", set " + std::to_string(set);
        EXPECT_NEAR(row.backgroundLuminance[set], direct.background[set],
                    1e-9 * direct.background[set])
            << where;
        const double lb = direct.background[set];
        EXPECT_NEAR(row.crosswise[set], 8 * std::log10(0.25 / lb * direct.crosswise), 1e-9)
            << where;
        EXPECT_NEAR(row.endwise[set], 8 * std::log10(0.25 / lb * direct.endwise), 1e-9) << where;
      }
    }
  }
}

TEST(UgrTable, TurningTheLuminaireByNinetyDegreesSwapsCrosswiseAndEndwise) {
  const PhotometricData data = ldt(asymmetricSpec(0.0));
  const PhotometricData turned = ldt(asymmetricSpec(90.0));
  const LightDistribution d0(data), d1(turned);
  const UgrTable t0 = computeUgrTable(tabularLuminaire(d0, data.opening), {});
  const UgrTable t1 = computeUgrTable(tabularLuminaire(d1, turned.opening), {});
  double largestDifference = 0.0;
  for (std::size_t i = 0; i < t0.rows.size(); ++i) {
    for (int set = 0; set < 5; ++set) {
      EXPECT_NEAR(t1.rows[i].crosswise[set], t0.rows[i].endwise[set], 1e-9);
      EXPECT_NEAR(t1.rows[i].endwise[set], t0.rows[i].crosswise[set], 1e-9);
      largestDifference = std::max(largestDifference,
                                   std::abs(t0.rows[i].crosswise[set] - t0.rows[i].endwise[set]));
    }
  }
  EXPECT_GT(largestDifference, 0.5);  // the luminaire does look different from the two sides
}

// A Lambertian panel, 600 mm x 600 mm, I = I0 cos γ (I0 = 1146 cd, 3600 lm): the cell 2H x 2H at
// S = 1.0H, 0.70/0.50/0.20, by hand. Four luminaires at T = ±1 m, R = 1 m and 3 m, H = 2 m; the
// near two have H/R = 2 > 1.9, outside Guth's range. The far two: r² = 14, cos γ = 2/√14,
// τ = atan(1/2), σ = atan(√5/3). L = I/(A cos γ); the flux fractions of I0 cos γ by the zones;
// F_T = 0.220, 0.422, 0.646 as CIE 190 prints them, whose rounding (±0.0005 each) bounds the
// difference.
TEST(UgrTable, LambertianPanelCellByHand) {
  testfiles::LdtSpec spec;
  spec.isym = 1;
  spec.areaLength = 600;
  spec.areaWidth = 600;
  spec.lampSets = {testfiles::LdtLampSet{1, 3600, 30}};
  spec.cdPerKlm = [](double, double gamma) { return testfiles::lambertian(1000.0 / kPi, gamma); };
  const PhotometricData data = ldt(spec);
  const LightDistribution d(data);
  const UgrTable table = computeUgrTable(tabularLuminaire(d, data.opening), {1.0, 2.0});
  const UgrTableRow& cell = table.rows.front();
  ASSERT_EQ(cell.room.acrossH, 2);
  ASSERT_EQ(cell.room.alongH, 2);
  EXPECT_EQ(cell.luminaires, 4);

  const double i0 = 3600.0 / kPi, area = 0.36, cosGamma = 2 / std::sqrt(14.0);
  const double gammaDeg = degrees(std::acos(cosGamma));
  const double intensity = d.intensity(TableAngles{0.0, gammaDeg});  // the table's, interpolated
  EXPECT_NEAR(intensity, i0 * cosGamma, i0 * (1 - std::cos(radians(2.5))));
  const double tau = degrees(std::atan(0.5)), sigma = degrees(std::atan(std::sqrt(5.0) / 3));
  const double p = std::exp((35.2 - 0.31889 * tau - 1.22 * std::exp(-2 * tau / 9)) * 1e-3 * sigma +
                            (21 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5 * sigma * sigma);
  const double luminance = intensity / (area * cosGamma);
  const double omega = area * cosGamma / 14.0;
  const double sum = 2 * luminance * luminance * omega / (p * p);

  // Zones: I0 cos(γ_mid) 2π(cos γ1 − cos γ2), the middles are nodes of the 5° table.
  double zone[9], flux = 0;
  for (int z = 0; z < 9; ++z) {
    zone[z] = i0 * std::cos(radians(10.0 * z + 5)) * 2 * kPi *
              (std::cos(radians(10.0 * z)) - std::cos(radians(10.0 * z + 10)));
    flux += zone[z];
  }
  const double c1 = zone[0] + zone[1] + zone[2] + zone[3] + 0.130 * zone[4];
  const double c2 = zone[0] + zone[1] + zone[2] + zone[3] + zone[4] + zone[5];
  const double c3 = c2 + zone[6] + 0.547 * zone[7];
  const double toFloor = (0.690 * c1 + 0.109 * c2 + 0.085 * c3 - 0.016 * flux) / flux;  // k = 1
  const double toWalls = 1 - toFloor;
  const double transfer = toFloor * 0.220 + toWalls * 0.422;
  const double background = 4 * flux / (2 * 2.0 * 8.0) * transfer / kPi;
  const double ugr = 8 * std::log10(0.25 / background * sum);
  // Bounds: F_T's rounding, and 0.130 and 0.547 for the cones' shares of their edge zones
  // (0.1302 and 0.5466), each moving F_DF by at most 0.0005 of the flux.
  const double bound = 8 / std::log(10.0) * (0.0005 + 0.0005 * 0.202) / transfer;
  EXPECT_NEAR(cell.backgroundLuminance[0], background, background * bound * std::log(10.0) / 8);
  EXPECT_NEAR(cell.crosswise[0], ugr, bound);
  EXPECT_NEAR(cell.endwise[0], ugr, bound);  // rotationally symmetric
}

TEST(UgrTable, FluxCorrectionIsEightLogOfTheFluxRatio) {
  const PhotometricData data = ldt(asymmetricSpec(0.0));
  testfiles::LdtSpec doubled = asymmetricSpec(0.0);
  doubled.lampSets = {testfiles::LdtLampSet{1, 8000, 60}};
  const PhotometricData twice = ldt(doubled);
  const LightDistribution d0(data), d1(twice);
  const UgrTable t0 = computeUgrTable(tabularLuminaire(d0, data.opening), {});
  const UgrTable t1 = computeUgrTable(tabularLuminaire(d1, twice.opening), {});
  EXPECT_NEAR(t1.fluxLm, 2 * t0.fluxLm, 1e-9 * t0.fluxLm);
  EXPECT_NEAR(t0.fluxLm, photometry::zonalFlux(d0), 1e-9 * t0.fluxLm);
  for (std::size_t i = 0; i < t0.rows.size(); ++i) {
    for (int set = 0; set < 5; ++set) {
      EXPECT_NEAR(t1.rows[i].crosswise[set] - t0.rows[i].crosswise[set], 8 * std::log10(2.0), 1e-9);
    }
  }
}

// A 600 mm x 300 mm opening with luminous sides 50 mm high (600 along C0-C180): seen along
// (1, 2, -2)/3 it shows its bottom times 2/3, the C0 face (300 x 50) times 1/3 and the C90 face
// (600 x 50) times 2/3: 0.12 + 0.005 + 0.02 = 0.145 m².
TEST(UgrTable, LuminousSidesAddTheirProjectedAreas) {
  testfiles::LdtSpec spec = asymmetricSpec(0.0);
  for (double& h : spec.areaHeights) h = 50;
  const PhotometricData data = ldt(spec);
  const LightDistribution d(data);
  const TabularLuminaire luminaire = tabularLuminaire(d, data.opening);
  EXPECT_NEAR(projectedArea(luminaire, Vec3(1, 2, -2) / 3.0), 0.145, 1e-12);
  EXPECT_NEAR(projectedArea(luminaire, Vec3(-1, -2, -2) / 3.0), 0.145, 1e-12);  // the other two
  EXPECT_NEAR(projectedArea(luminaire, Vec3(0, 0, -1)), 0.18, 1e-12);
}

TEST(UgrTable, LuminaireWithoutFlatAreaIsRefused) {
  testfiles::LdtSpec spec;
  spec.isym = 1;
  spec.cdPerKlm = [](double, double gamma) { return testfiles::lambertian(300.0, gamma); };
  const PhotometricData data = ldt(spec);
  const LightDistribution d(data);
  const TabularLuminaire luminaire = tabularLuminaire(d, data.opening);
  EXPECT_EQ(luminaire.areaM2, 0.0);
  EXPECT_THROW(computeUgrTable(luminaire, {}), std::invalid_argument);
}

}  // namespace
}  // namespace penumbra
