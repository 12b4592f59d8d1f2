// The sun (docs/method.md, "The sun"): its position by NOAA's algorithm against published
// values, the `sun:` key of a scene, and the sunlight of a disk of 0.53° through openings
// against closed forms and the geometric projection of a window.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <span>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "geometry/angles.hpp"
#include "grid/grid_evaluation.hpp"
#include "illuminance/estimator.hpp"
#include "illuminance/sunlight.hpp"
#include "output/grid_rows.hpp"
#include "output/result_files.hpp"
#include "output/result_reader.hpp"
#include "output/summary_table.hpp"
#include "sanitized_build.hpp"
#include "scene/scene_loader.hpp"
#include "scene/solar_position.hpp"
#include "scene_errors.hpp"
#include "study/case_fingerprint.hpp"
#include "study/study_cases.hpp"
#include "study/study_plan.hpp"
#include "study/study_reader.hpp"

namespace penumbra {
namespace {

using testing::sceneErrorOf;

constexpr double kAngleTolerance = 0.01;  // °: the accuracy the solar position is checked to

LocalInstant at(CivilDate date, int hours, int minutes, int seconds, double timezoneHours) {
  return LocalInstant{date, hours * 3600.0 + minutes * 60.0 + seconds, timezoneHours};
}

// The difference of two azimuths (°), in [−180, 180).
double azimuthDifference(double a, double b) {
  return std::remainder(a - b, 360.0);
}

// ---- the solar position against published values

// Reda & Andreas, "Solar Position Algorithm for Solar Radiation Applications", NREL/TP-560-34302
// (2003, rev. 2008), the worked example (Golden, Colorado, 17 October 2003 12:30:30 at UTC−7),
// and the same instant a day later as pvlib's test suite gives it from the NREL SPA
// (pvlib/tests/test_solarposition.py, expected_solpos_multi): the topocentric azimuth and the
// elevation without refraction. The SPA's position is topocentric: the parallax lowers it by
// 8.8″·cos(elevation) = 0.0019° against this geocentric algorithm, within the tolerance.
struct PublishedPosition {
  const char* what;
  LocalInstant instant;
  GeographicSite site;
  double azimuthDegrees, elevationDegrees;
};

TEST(SolarPosition, MatchesTheNrelSpaExample) {
  const GeographicSite golden{39.742476, -105.1786};
  const PublishedPosition cases[] = {
      {"SPA report example", at({2003, 10, 17}, 12, 30, 30, -7.0), golden, 194.340241, 39.872046},
      {"pvlib, SPA, a day later", at({2003, 10, 18}, 12, 30, 30, -7.0), golden, 194.311132,
       39.505196},
  };
  for (const PublishedPosition& c : cases) {
    const SolarPosition p = solarPosition(c.instant, c.site);
    EXPECT_NEAR(azimuthDifference(p.azimuthDegrees, c.azimuthDegrees), 0.0, kAngleTolerance)
        << c.what;
    EXPECT_NEAR(p.elevationDegrees, c.elevationDegrees, kAngleTolerance) << c.what;
  }
}

// Meeus, "Astronomical Algorithms" (2nd ed.), example 25.a: the Sun on 1992 October 13.0 TD,
// apparent declination −7.78507°; example 28.b: the equation of time that day, 13.70940 min
// (0.25° of hour angle a minute). TD and UT differ by ΔT ≈ 59 s, 0.0003° of declination.
TEST(SolarPosition, MatchesMeeusDeclinationAndEquationOfTime) {
  const SolarPosition p = solarPosition(at({1992, 10, 13}, 0, 0, 0, 0.0), GeographicSite{});
  EXPECT_NEAR(p.declinationDegrees, -7.78507, kAngleTolerance);
  EXPECT_NEAR(0.25 * p.equationOfTimeMinutes, 0.25 * 13.70940, kAngleTolerance);
}

// Sunrise, transit and sunset from the NREL SPA web calculator, as pvlib's test suite gives them
// (expected_rise_set_spa, test_sun_rise_set_transit_spa: ΔT 65 s), at Golden (northern
// hemisphere, 2 January and 2 August 2015, UTC−7) and at 35° S 0° E (southern hemisphere, 5 July
// 1996 and 4 December 2004, UTC). The SPA's sunrise and sunset are the instants the centre's
// geometric elevation is −0.8333° (34′ of refraction and 16′ of semidiameter); its transit the
// instant the sun crosses the meridian: azimuth 180° north of the sun's declination, 0° south of
// it. The times are rounded to the second: at sunrise and sunset the elevation changes by at
// most 0.0035°/s there (0.0018° over the half second of rounding, checked at the instant
// given); at transit the azimuth turns by up to 0.018°/s, so the check is that the azimuth
// passes within 0.01° of the meridian in the half second either side of it.
struct PublishedEvent {
  const char* what;
  LocalInstant instant;
  GeographicSite site;
};

TEST(SolarPosition, SunriseAndSunsetOfTheNrelSpaCalculator) {
  constexpr double kRiseSetElevation = -0.8333;  // °
  const GeographicSite golden{39.742476, -105.1786}, south{-35.0, 0.0};
  // Left out: Golden's sunset on 2 August 2015 (19:13:58) in that table lies 29 s after the
  // instant symmetric to its sunrise (05:00:27) about its transit (12:06:58), where the
  // declination's fall between them (0.15°) moves the sunset earlier, not later; the elevation
  // there is 0.19° below −0.8333°, the position of an instant about 55 s after sunset.
  const PublishedEvent cases[] = {
      {"Golden sunrise 2015-01-02", at({2015, 1, 2}, 7, 21, 55, -7.0), golden},
      {"Golden sunset 2015-01-02", at({2015, 1, 2}, 16, 47, 43, -7.0), golden},
      {"Golden sunrise 2015-08-02", at({2015, 8, 2}, 5, 0, 27, -7.0), golden},
      {"35 S sunrise 1996-07-05", at({1996, 7, 5}, 7, 8, 15, 0.0), south},
      {"35 S sunset 1996-07-05", at({1996, 7, 5}, 17, 1, 4, 0.0), south},
      {"35 S sunrise 2004-12-04", at({2004, 12, 4}, 4, 38, 57, 0.0), south},
      {"35 S sunset 2004-12-04", at({2004, 12, 4}, 19, 2, 3, 0.0), south},
  };
  for (const PublishedEvent& c : cases)
    EXPECT_NEAR(solarPosition(c.instant, c.site).elevationDegrees, kRiseSetElevation,
                kAngleTolerance)
        << c.what;
}

TEST(SolarPosition, TransitOfTheNrelSpaCalculator) {
  const GeographicSite golden{39.742476, -105.1786}, south{-35.0, 0.0};
  const struct {
    PublishedEvent event;
    double meridianAzimuth;  // °
  } cases[] = {
      {{"Golden transit 2015-01-02", at({2015, 1, 2}, 12, 4, 45, -7.0), golden}, 180.0},
      {{"Golden transit 2015-08-02", at({2015, 8, 2}, 12, 6, 58, -7.0), golden}, 180.0},
      {{"35 S transit 1996-07-05", at({1996, 7, 5}, 12, 4, 36, 0.0), south}, 0.0},
      {{"35 S transit 2004-12-04", at({2004, 12, 4}, 11, 50, 22, 0.0), south}, 0.0},
  };
  for (const auto& c : cases) {
    LocalInstant before = c.event.instant, after = c.event.instant;
    before.secondsOfDay -= 0.5;
    after.secondsOfDay += 0.5;
    // The azimuth grows through the transit (east to west): it lies within 0.01° of the
    // meridian somewhere in the half second either side of the published instant.
    const double early =
        azimuthDifference(solarPosition(before, c.event.site).azimuthDegrees, c.meridianAzimuth);
    const double late =
        azimuthDifference(solarPosition(after, c.event.site).azimuthDegrees, c.meridianAzimuth);
    const bool north = c.meridianAzimuth == 180.0;
    // North of the sun's path the azimuth turns from east to west through south (increasing);
    // south of it through north (decreasing).
    const double lo = north ? early : late, hi = north ? late : early;
    EXPECT_LE(lo, kAngleTolerance) << c.event.what;
    EXPECT_GE(hi, -kAngleTolerance) << c.event.what;
    EXPECT_LT(std::abs(lo), 1.0) << c.event.what;  // near the meridian at all
  }
}

TEST(SolarPosition, RefractionLiftsTheSunNearTheHorizonOnly) {
  // NOAA's standard atmosphere: 34.6′ less the fit's error at the horizon, about 1′ at 45°, none
  // at the zenith (above 85°).
  const GeographicSite equator{0.0, 0.0};
  for (int minute = 0; minute < 24 * 60; minute += 7) {
    const SolarPosition p = solarPosition(at({2026, 3, 21}, 0, minute, 0, 0.0), equator);
    const double lift = p.apparentElevationDegrees - p.elevationDegrees;
    if (p.elevationDegrees > 85.0) {
      EXPECT_EQ(lift, 0.0);
    }
    if (p.elevationDegrees > 0.0) {
      EXPECT_LE(lift, 0.5 + 1e-9);
    }
    if (std::abs(p.elevationDegrees - 45.0) < 1.0) {
      EXPECT_NEAR(lift, 1.0 / 60.0, 0.1 / 60.0);
    }
  }
}

TEST(SolarPosition, DirectionInTheScenesFrame) {
  // north_deg 0: north +y, east +x; north_deg 90: north −x (counter-clockwise from +y seen from
  // above), east +y.
  EXPECT_TRUE(sunDirection(0.0, 0.0, 0.0).isApprox(Vec3(0, 1, 0), 1e-15));
  EXPECT_TRUE(sunDirection(90.0, 0.0, 0.0).isApprox(Vec3(1, 0, 0), 1e-15));
  EXPECT_TRUE(sunDirection(0.0, 0.0, 90.0).isApprox(Vec3(-1, 0, 0), 1e-15));
  EXPECT_TRUE(sunDirection(90.0, 0.0, 90.0).isApprox(Vec3(0, 1, 0), 1e-15));
  const Vec3 d = sunDirection(180.0, 30.0, 0.0);  // south, 30° up
  EXPECT_NEAR(d.z(), 0.5, 1e-15);
  EXPECT_NEAR(d.y(), -std::sqrt(3.0) / 2.0, 1e-15);
}

// ---- the `sun:` key

std::string sunScene(const std::string& sun, bool withSite = true) {
  std::string yaml = "penumbra: 1\n";
  if (withSite)
    yaml += "site: {latitude_deg: 51.5, longitude_deg: -0.1, timezone_h: 0, north_deg: 30}\n";
  yaml += sun + "\n";
  yaml += "solids:\n  - {name: block, box: {min: [0, 0, 0], max: [1, 1, 1]}}\n";
  return yaml;
}

TEST(SunKey, PlacesTheSunAtTheSitesDateAndTime) {
  const Scene scene = parseScene(
      sunScene("sun: {date: 2026-03-21, time: \"10:00\", direct_normal_illuminance_lx: 60000}"),
      "sun.yaml");
  ASSERT_TRUE(scene.sun);
  EXPECT_EQ(scene.sun->directNormalIlluminance, 60000.0);
  const SolarPosition expected =
      solarPosition(at({2026, 3, 21}, 10, 0, 0, 0.0), GeographicSite{51.5, -0.1});
  EXPECT_EQ(scene.sun->position.azimuthDegrees, expected.azimuthDegrees);
  EXPECT_TRUE(scene.sun->aboveHorizon());
  EXPECT_TRUE(scene.sun->direction.isApprox(
      sunDirection(expected.azimuthDegrees, expected.apparentElevationDegrees, 30.0), 1e-15));
  // Seconds may be given.
  const Scene later = parseScene(
      sunScene("sun: {date: 2026-03-21, time: \"10:00:30\", direct_normal_illuminance_lx: 1}"),
      "sun.yaml");
  EXPECT_EQ(later.sun->instant.secondsOfDay, 36030.0);
}

// `hour:` in decimal hours is the same instant as `time:` in HH:MM:SS, and parameters may give
// it and north_deg through expressions.
TEST(SunKey, DecimalHourAndNorthFromParametersPlaceTheSunAsTheClockTimeDoes) {
  const auto sunWith = [](const std::string& site, const std::string& time,
                          const ParameterValues& values) {
    const std::string yaml = "penumbra: 1\nparameters: {hour: 12.0, north: 0.0}\n" + site +
                             "\nsun: {date: 2026-03-21, " + time +
                             ", direct_normal_illuminance_lx: 60000}\n"
                             "solids:\n  - {name: block, box: {min: [0, 0, 0], max: [1, 1, 1]}}\n";
    const Scene scene = parseScene(yaml, "sun.yaml", values);
    return *scene.sun;
  };
  const std::string fixedSite =
      "site: {latitude_deg: 51.5, longitude_deg: -0.1, timezone_h: 0, north_deg: 30}";
  const std::string parameterSite =
      "site: {latitude_deg: 51.5, longitude_deg: -0.1, timezone_h: 0, north_deg: \"${north}\"}";
  const Sun clock = sunWith(fixedSite, "time: \"10:45\"", {});
  const Sun decimal = sunWith(fixedSite, "hour: 10.75", {});
  EXPECT_EQ(decimal.instant.secondsOfDay, clock.instant.secondsOfDay);  // 10.75 h = 10:45
  EXPECT_EQ(decimal.position.azimuthDegrees, clock.position.azimuthDegrees);
  EXPECT_TRUE(decimal.direction.isApprox(clock.direction, 1e-15));

  const Sun swept = sunWith(parameterSite, "hour: \"${hour}\"", {{"hour", 10.75}, {"north", 30.0}});
  EXPECT_EQ(swept.instant.secondsOfDay, clock.instant.secondsOfDay);
  EXPECT_TRUE(swept.direction.isApprox(clock.direction, 1e-15));
  // Turning north by 90° turns the sun's direction about z by 90° (counter-clockwise from above).
  const Sun turned =
      sunWith(parameterSite, "hour: \"${hour}\"", {{"hour", 10.75}, {"north", 120.0}});
  const Vec3 s = clock.direction;
  EXPECT_TRUE(turned.direction.isApprox(Vec3(-s.y(), s.x(), s.z()), 1e-12))
      << turned.direction.transpose() << " vs " << s.transpose();
}

TEST(SunKey, ErrorsNameTheLineAndKey) {
  const struct {
    std::string sun;
    const char* key;
    const char* words;
  } cases[] = {
      {"sun: {date: 2026-02-29, time: \"10:00\", direct_normal_illuminance_lx: 1}", "sun.date",
       "not a day of the calendar"},
      {"sun: {date: 21.03.2026, time: \"10:00\", direct_normal_illuminance_lx: 1}", "sun.date",
       "YYYY-MM-DD"},
      {"sun: {date: 2026-03-21, time: \"24:00\", direct_normal_illuminance_lx: 1}", "sun.time",
       "not a time of day"},
      {"sun: {date: 2026-03-21, time: \"10h\", direct_normal_illuminance_lx: 1}", "sun.time",
       "HH:MM"},
      {"sun: {date: 2026-03-21, time: \"10:00\", direct_normal_illuminance_lx: 0}",
       "sun.direct_normal_illuminance_lx", ""},
      {"sun: {date: 2026-03-21, time: \"10:00\", direct_normal_illuminance_lx: 1, azimuth: 3}",
       "sun", "azimuth"},
      {"sun: {date: 2026-03-21, hour: 24, direct_normal_illuminance_lx: 1}", "sun.hour",
       "up to (not including) 24"},
      {"sun: {date: 2026-03-21, hour: -0.5, direct_normal_illuminance_lx: 1}", "sun.hour",
       "from 0"},
      {"sun: {date: 2026-03-21, time: \"10:00\", hour: 10, direct_normal_illuminance_lx: 1}",
       "sun.hour", "not both"},
      {"sun: {date: 2026-03-21, direct_normal_illuminance_lx: 1}", "sun.time", "'hour'"},
      {"sun: {date: 2026-03-21, time: \"${h}:00\", direct_normal_illuminance_lx: 1}", "sun.time",
       "give 'hour:'"},
  };
  for (const auto& c : cases) {
    const SceneError e = sceneErrorOf(sunScene(c.sun), "sun.yaml");
    EXPECT_EQ(e.line(), 3) << c.sun;
    EXPECT_EQ(e.key().rfind(c.key, 0), 0u) << c.sun << ": " << e.what();
    EXPECT_NE(std::string(e.what()).find(c.words), std::string::npos) << e.what();
  }
  const SceneError noSite = sceneErrorOf(
      sunScene("sun: {date: 2026-03-21, time: \"10:00\", direct_normal_illuminance_lx: 1}", false),
      "sun.yaml");
  EXPECT_EQ(noSite.line(), 2);
  EXPECT_EQ(noSite.key(), "sun");
  EXPECT_NE(std::string(noSite.what()).find("needs the site"), std::string::npos);
}

// ---- the sunlight of the disk

// Puts the scene's sun in direction `s` (unit), E_dn `directNormal`.
void setSun(Scene& scene, const Vec3& s, double directNormal) {
  Sun sun;
  sun.directNormalIlluminance = directNormal;
  sun.direction = s;
  sun.position.apparentElevationDegrees = std::asin(s.z()) * kDegreesPerRadian;
  sun.position.elevationDegrees = sun.position.apparentElevationDegrees;
  scene.sun = sun;
}

double sunAt(const Scene& scene, const Vec3& position, const Vec3& normal, int solid = -1) {
  const SamplePoint point{position, normal, solid};
  return sunlight(scene, std::span<const SamplePoint>(&point, 1)).front();
}

TEST(Sunlight, UnobstructedPointGetsTheDirectNormalIlluminanceTimesTheCosine) {
  // A block beside the points, not between them and the sun.
  Scene scene =
      parseScene("penumbra: 1\nsolids:\n  - {name: block, box: {min: [5, 5, 0], max: [6, 6, 1]}}\n",
                 "open.yaml");
  const Vec3 s = Vec3(0.3, -0.5, 0.6).normalized();
  setSun(scene, s, 60000.0);
  // Horizontal: E_dn·sin(altitude); facing the sun: E_dn; tilted: E_dn·n·s; facing away: 0.
  EXPECT_NEAR(sunAt(scene, Vec3(1, 1, 0), Vec3::UnitZ()), 60000.0 * s.z(), 1e-9 * 60000.0);
  EXPECT_NEAR(sunAt(scene, Vec3(1, 2, 0.5), s), 60000.0, 1e-9 * 60000.0);
  const Vec3 tilted = Vec3(0.2, 0.1, 1.0).normalized();
  EXPECT_NEAR(sunAt(scene, Vec3(2, 1, 0.3), tilted), 60000.0 * tilted.dot(s), 1e-9 * 60000.0);
  EXPECT_EQ(sunAt(scene, Vec3(2, 1, 0.3), -s), 0.0);
}

TEST(Sunlight, ASunBelowTheHorizonGivesNothing) {
  Scene scene =
      parseScene("penumbra: 1\nsolids:\n  - {name: block, box: {min: [5, 5, 0], max: [6, 6, 1]}}\n",
                 "open.yaml");
  const Vec3 s = Vec3(0.3, -0.5, -0.1).normalized();
  setSun(scene, s, 60000.0);
  ASSERT_FALSE(scene.sun->aboveHorizon());
  // A point facing the sun would see it, were it above the horizon.
  EXPECT_EQ(sunAt(scene, Vec3(1, 1, 0), s), 0.0);
}

TEST(Sunlight, TheLuminanceGivesExactlyTheDirectNormalIlluminance) {
  // The polygon's projected solid angle: for a regular N-gon of circumradius angle a seen
  // from its axis, Lambert's formula sums over the edges θ_k·cos γ_k with θ_k the edge's angle
  // at the eye and γ_k the angle of its plane to the axis; written here from the vertices.
  const double a = 0.5 * kSunDiameterDegrees * kRadiansPerDegree;
  const int n = kSunPolygonSides;
  double sum = 0.0;
  for (int k = 0; k < n; ++k) {
    const double p0 = 2.0 * std::numbers::pi * k / n, p1 = 2.0 * std::numbers::pi * (k + 1) / n;
    const Vec3 v0(std::sin(a) * std::cos(p0), std::sin(a) * std::sin(p0), std::cos(a));
    const Vec3 v1(std::sin(a) * std::cos(p1), std::sin(a) * std::sin(p1), std::cos(a));
    const Vec3 m = v0.cross(v1);
    sum += std::atan2(m.norm(), v0.dot(v1)) * m.normalized().z();
  }
  const double projected = 0.5 * sum;
  EXPECT_NEAR(sunLuminance(1.0) * projected, 1.0, 1e-12);
  // About E_dn / (π sin² a), the disk's.
  EXPECT_NEAR(sunLuminance(1.0) * std::numbers::pi * std::pow(std::sin(a), 2), 1.0, 0.01);
}

// A room 6 × 5 × 3 m, walls 0.2 m thick, a window in wall y0 (y from −0.2 to 0) from x = 2 to 4
// and z = 0.9 to 2.4; the sun towards s = (0.45, −0.7, 0.55)/|.|: it enters through the window
// and falls on the floor.
constexpr double kWall = 0.2, kLeft = 2.0, kRight = 4.0, kSill = 0.9, kHead = 2.4;

Scene windowScene(double transmittance) {
  Scene scene = parseScene(
      "penumbra: 1\nroom:\n  size: [6, 5, 3]\n  wall_thickness: 0.2\n  openings:\n"
      "    - {name: w1, wall: y0, x: 2.0, z: 0.9, width: 2.0, height: 1.5, transmittance: " +
          std::to_string(transmittance) + "}\n",
      "window.yaml");
  setSun(scene, Vec3(0.45, -0.7, 0.55).normalized(), 60000.0);
  return scene;
}

int floorOf(const Scene& scene) {
  for (int i = 0; i < static_cast<int>(scene.solids.size()); ++i)
    if (scene.solids[i].name == "room.floor") return i;
  return -1;
}

double floorSun(const Scene& scene, double x, double y) {
  return sunAt(scene, Vec3(x, y, 0.0), Vec3::UnitZ(), floorOf(scene));
}

// The x in [lo, hi] where the floor's E_sun along the line at `y` crosses `level` (E grows with
// x when `rising`), by bisection to 1e-10 m.
double crossing(const Scene& scene, double y, double lo, double hi, double level, bool rising) {
  while (hi - lo > 1e-10) {
    const double mid = 0.5 * (lo + hi);
    const bool above = floorSun(scene, mid, y) > level;
    ((above == rising) ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(Sunlight, PenumbraOfTheJambsWhereTheProjectionThroughTheSunsCentrePutsIt) {
  const Scene scene = windowScene(1.0);
  const Vec3 s = scene.sun->direction;
  const double full = 60000.0 * s.z();  // a floor point that sees the whole disk
  const double r = 0.5 * kSunDiameterDegrees * kRadiansPerDegree;
  const double y = 2.2;  // the line of floor points; rays to the sun cross the window's middle
  // The ray P + λs meets the inner face (y = 0) at λ0 and the outer one (y = −kWall) at λ1 > λ0;
  // with s_x > 0 it moves towards +x: the left jamb's inner edge and the right jamb's outer edge
  // bound the patch.
  const double l0 = y / -s.y(), l1 = (y + kWall) / -s.y();
  ASSERT_GT(l0 * s.z(), kSill + 0.1);
  ASSERT_LT(l1 * s.z(), kHead - 0.1);
  const double leftEdge = kLeft - l0 * s.x();  // the projection through the sun's centre
  const double rightEdge = kRight - l1 * s.x();
  // The full patch at the line's middle.
  EXPECT_NEAR(floorSun(scene, 0.5 * (leftEdge + rightEdge), y), full, 1e-9 * full);

  // Along x at fixed y the penumbra is wider than across the shadow line (which runs along s's
  // horizontal part) by |s_h| / |s_y|.
  const double stretch = std::hypot(s.x(), s.y()) / -s.y();
  const struct {
    const char* edge;
    double projected, distance;
    bool rising;
  } edges[] = {{"left jamb (inner edge)", leftEdge, l0, true},
               {"right jamb (outer edge)", rightEdge, l1, false}};
  for (const auto& e : edges) {
    const double reach = 2.0 * r * e.distance * stretch;  // more than half the width
    const double lo = e.projected - reach, hi = e.projected + reach;
    // The midpoint: half the disk hidden. The plane through P and the vertical edge holds the
    // sun's centre and the floor's normal, so the two halves give the same light.
    const double mid = crossing(scene, y, lo, hi, 0.5 * full, e.rising);
    EXPECT_NEAR(mid, e.projected, 1e-6) << e.edge;
    // The width: from the first point that sees any of the disk to the first that sees all of
    // it, across the shadow line. A disk of angular diameter 2r at distance d gives 2r·d; the
    // 32-gon's width across any direction lies between 2r·cos(π/32) and 2r. Second-order terms
    // in r (r² = 2e-5) bound the rest.
    const double start = crossing(scene, y, lo, hi, 1e-9 * full, e.rising);
    const double end = crossing(scene, y, lo, hi, (1.0 - 1e-9) * full, e.rising);
    const double width = std::abs(end - start) / stretch;
    EXPECT_GE(width,
              2.0 * r * std::cos(std::numbers::pi / kSunPolygonSides) * e.distance * (1.0 - 1e-4))
        << e.edge;
    EXPECT_LE(width, 2.0 * r * e.distance * (1.0 + 1e-4)) << e.edge;
    EXPECT_NEAR(width / e.distance, 0.0093, 0.0001) << e.edge;  // about 1 cm a metre
  }
}

// How far inside the geometric projection of the window a floor point is (m, at the wall's
// faces; negative outside): the least clearance of the central ray from the hole's edges on the
// inner and the outer face, each less the reach there of the rays within r of it.
double clearance(const Vec3& s, double x, double y) {
  const double r = 0.5 * kSunDiameterDegrees * kRadiansPerDegree;
  double least = 1e300;
  for (double depth : {0.0, kWall}) {
    const double l = (y + depth) / -s.y();
    const double hx = x + l * s.x(), hz = l * s.z();
    const double reach = 1.01 * l * std::tan(r) / -s.y();  // the disk's rays on the face's plane
    least = std::min(
        {least, hx - kLeft - reach, kRight - hx - reach, hz - kSill - reach, kHead - hz - reach});
  }
  return least;
}

double clearanceOutside(const Vec3& s, double x, double y) {
  const double r = 0.5 * kSunDiameterDegrees * kRadiansPerDegree;
  double most = -1e300;
  for (double depth : {0.0, kWall}) {
    const double l = (y + depth) / -s.y();
    const double hx = x + l * s.x(), hz = l * s.z();
    const double reach = 1.01 * l * std::tan(r) / -s.y();
    most = std::max(
        {most, kLeft - hx - reach, hx - kRight - reach, kSill - hz - reach, hz - kHead - reach});
  }
  return most;
}

TEST(Sunlight, PatchOutlineIsTheGeometricProjectionOfTheWindow) {
  const Scene scene = windowScene(1.0);
  const Vec3 s = scene.sun->direction;
  const double full = 60000.0 * s.z();
  int lit = 0, dark = 0;
  for (double x = 0.05; x < 6.0; x += 0.1)
    for (double y = 0.05; y < 5.0; y += 0.1) {
      const double e = floorSun(scene, x, y);
      if (clearance(s, x, y) > 0.0) {
        EXPECT_NEAR(e, full, 1e-9 * full) << x << ", " << y;
        ++lit;
      } else if (clearanceOutside(s, x, y) > 0.0) {
        EXPECT_LE(e, 1e-9 * full) << x << ", " << y;
        ++dark;
      }
    }
  EXPECT_GT(lit, 50);
  EXPECT_GT(dark, 1000);
}

TEST(Sunlight, GlazingScalesTheSunByItsTransmittance) {
  // The sun through an opening counts once, times the opening's τ, as the sky does: everywhere,
  // the penumbra included.
  const Scene clear = windowScene(1.0), glazed = windowScene(0.7);
  const Vec3 s = clear.sun->direction;
  const double y = 2.2, leftEdge = kLeft - y / -s.y() * s.x();
  int sunlit = 0;
  for (double x = leftEdge - 0.05; x < leftEdge + 2.0; x += 0.0123) {
    const double e = floorSun(clear, x, y);
    EXPECT_NEAR(floorSun(glazed, x, y), 0.7 * e, 1e-12 * 60000.0) << x;
    if (e > 0.0) ++sunlit;
  }
  EXPECT_GT(sunlit, 100);
}

// ---- the sun in a grid's figures

// One grid of a data/ example streamed through the kernel on the CPU, with interreflection.
// What the tests below hold of these runs (the sun adds light, the daylight factor leaves it out
// to rounding) holds on any mesh: the sanitizer build, where the host's sunlight on the elements
// runs many times slower, takes the faces in elements unrefined.
GridRun exampleGrid(const Scene& scene, const std::string& name) {
  EstimatorOptions options;
  options.device = "cpu";
  if (testing::kSanitizedBuild) options.mesh.refinementLevels = 0;
  Estimator estimator(options, scene);
  for (const CalculationGrid& grid : scene.grids)
    if (grid.name == name)
      return streamGrid(scene, grid, estimator.function(), estimator.batchSize(), GridBatchSink{});
  ADD_FAILURE() << "no grid " << name;
  return {};
}

TEST(SunInGrids, TheDaylightFactorLeavesTheSunOut) {
  // data/office-sun.yaml is data/office-daylight.yaml with a sun: the same daylight factor, with
  // more light.
  const Scene daylight = loadScene(PENUMBRA_SOURCE_DIR "/data/office-daylight.yaml");
  const Scene sunny = loadScene(PENUMBRA_SOURCE_DIR "/data/office-sun.yaml");
  ASSERT_FALSE(daylight.sun);
  ASSERT_TRUE(sunny.sun && sunny.sun->aboveHorizon());
  const GridRun without = exampleGrid(daylight, "reference-plane");
  const GridRun with = exampleGrid(sunny, "reference-plane");
  ASSERT_TRUE(without.daylight && with.daylight && with.sun);
  EXPECT_FALSE(without.sun);
  // The sun reaches part of the plane and adds to E.
  EXPECT_GT(with.sun->eMax, 1000.0);
  EXPECT_GT(with.sun->sunlitShare, 0.0);
  EXPECT_LT(with.sun->sunlitShare, 1.0);
  // The sun adds its direct light and, reflected by the room, more.
  EXPECT_GT(with.metrics.eAvg - without.metrics.eAvg, with.sun->eAvg);
  // The mesh does not follow the sun and the sun's light is solved alone, so E − E_sun −
  // E_sun,reflected rounds the sun's parts away within 1e-16 of E: the figures agree to 1e-12.
  const DaylightMetrics& a = *without.daylight;
  const DaylightMetrics& b = *with.daylight;
  const std::pair<double, double> figures[] = {
      {a.mean, b.mean}, {a.median, b.median},         {a.min, b.min},
      {a.max, b.max},   {a.directMean, b.directMean}, {a.internalMean, b.internalMean}};
  for (const auto& [x, y] : figures) EXPECT_NEAR(y, x, 1e-12 * a.max);
  EXPECT_EQ(a.shareAtLeast, b.shareAtLeast);
  ASSERT_TRUE(a.provision && b.provision);
  EXPECT_EQ(a.provision->reached(), b.provision->reached());
}

TEST(SunInGrids, CsvRowsCarryTheSunAndTheDaylightFactorWithoutIt) {
  EXPECT_EQ(gridCsvHeader(true, true, true),
            "x_m,y_m,z_m,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_sun_lx,E_sun_reflected_lx,"
            "DF_pct,DF_direct_pct,DF_internal_pct,SC_pct,ERC_pct,IRC_pct,inside\n");
  EXPECT_EQ(gridCsvHeader(false, false, true), "x_m,y_m,z_m,nx,ny,nz,E_lx,E_sun_lx,inside\n");
  GridRows rows(NumberDigits::Double);
  rows.setOutdoorIlluminance(10000.0);
  rows.setSunColumn(true);
  const double direct = 1200.0, sky = 150.0, external = 50.0;
  rows.add(Vec3(1, 2, 0.85), Vec3::UnitZ(),
           GridRowValues{1300.0, &direct, 1000.0, 50.0, &sky, &external}, "");
  // E 1300 lx: 1200 direct (1000 of it the sun's, 150 the sky's, 50 the ground's), 100
  // reflected (50 of it the sun's): DF (1300 − 1000 − 50) / 100 = 2.5 %, 2 % direct, 0.5 %
  // internal; SC 1.5 %, ERC 0.5 %, IRC 2.5 − 1.5 − 0.5 = 0.5 %.
  EXPECT_EQ(rows.csv(), "1,2,0.85,0,0,1,1300,1200,100,1000,50,2.5,2,0.5,1.5,0.5,0.5,\n");
}

TEST(SunInGrids, ASweepCaseIsComputedAgainWhenTheSunChanges) {
  const auto fingerprint = [](const std::string& sun, double north) {
    const std::string yaml =
        "penumbra: 1\nsite: {latitude_deg: 51.5, longitude_deg: -0.1, north_deg: " +
        std::to_string(north) + "}\n" + sun +
        "\nsolids:\n  - {name: block, box: {min: [0, 0, 0], max: [1, 1, 1]}}\n"
        "grids:\n  - {name: g, points: [[2, 2, 0, 0, 0, 1]]}\n";
    return caseFingerprint(parseScene(yaml, "case.yaml"), CaseOutputs{{"g"}, "kernel", {}});
  };
  const std::string ten =
      "sun: {date: 2026-03-21, time: \"10:00\", direct_normal_illuminance_lx: 60000}";
  const std::string base = fingerprint(ten, 0.0);
  EXPECT_EQ(fingerprint(ten, 0.0), base);
  EXPECT_NE(fingerprint("", 0.0), base);
  EXPECT_NE(fingerprint(ten, 15.0), base);
  EXPECT_NE(
      fingerprint("sun: {date: 2026-03-21, time: \"11:00\", direct_normal_illuminance_lx: 60000}",
                  0.0),
      base);
  EXPECT_NE(
      fingerprint("sun: {date: 2026-06-21, time: \"10:00\", direct_normal_illuminance_lx: 60000}",
                  0.0),
      base);
  EXPECT_NE(
      fingerprint("sun: {date: 2026-03-21, time: \"10:00\", direct_normal_illuminance_lx: 50000}",
                  0.0),
      base);
}

TEST(SunInGrids, TheTableAndSummaryGiveEsunAndTheSunlitShare) {
  RunReport run;
  run.sun = SunReport{145.25, 31.5, 60000.0, true};
  GridReport grid;
  grid.name = "plane";
  grid.kind = GridKind::WorkPlane;
  // Four points: E_sun 0, 0, 2000 and 6000 lx: mean 2000, max 6000, sunlit 50 %.
  SunMetricsSum sums;
  for (double e : {0.0, 0.0, 2000.0, 6000.0}) sums.add(e, false);
  sums.add(9999.0, true);  // inside a solid: left out
  grid.sunMetrics = sums.metrics();
  run.grids.push_back(grid);
  const std::string table = summaryTable(run);
  EXPECT_NE(table.find("Sun: azimuth 145.25° (from north towards east), elevation 31.50°, E_dn "
                       "60000 lx"),
            std::string::npos)
      << table;
  for (const char* header : {"Esun avg [lx]", "Esun max [lx]", "sunlit [% of points]"})
    EXPECT_NE(table.find(header), std::string::npos) << header << "\n" << table;
  EXPECT_NE(table.find("2000.0 |        6000.0 |                50.00"), std::string::npos)
      << table;
  const nlohmann::json summary = summaryJson(run);
  EXPECT_EQ(summary["sun"]["azimuth_deg"], 145.25);
  EXPECT_EQ(summary["sun"]["above_horizon"], true);
  EXPECT_EQ(summary["grids"][0]["sun"]["Esun_avg_lx"], 2000.0);
  EXPECT_EQ(summary["grids"][0]["sun"]["Esun_max_lx"], 6000.0);
  EXPECT_EQ(summary["grids"][0]["sun"]["sunlit_share_pct"], 50.0);

  run.sun->aboveHorizon = false;
  EXPECT_NE(summaryTable(run).find("Sun: below the horizon: no direct sunlight"),
            std::string::npos);
}

TEST(SunInGrids, TheCsvReadsBackWithItsSunColumn) {
  // `penumbra plot` reads the CSV a sunny run wrote: E, its parts, E_sun and its reflection come
  // back.
  GridReport written;
  written.name = "plane";
  written.points = {SamplePoint{Vec3(1, 2, 0.85), Vec3::UnitZ(), -1},
                    SamplePoint{Vec3(1.5, 2, 0.85), Vec3::UnitZ(), -1}};
  written.insideSolids = {"", ""};
  written.illuminance = {1300.0, 300.0};
  written.direct = {1200.0, 200.0};
  written.sun = {1000.0, 0.0};
  written.sunReflected = {50.0, 0.0};
  written.sunMetrics = SunMetrics{500.0, 1000.0, 0.5};
  written.daylight = DaylightMetrics{};
  written.daylight->outdoorIlluminance = 10000.0;
  std::stringstream text;
  writeGridCsv(text, written, NumberDigits::Double);
  GridReport read;
  readGridCsv(text, "plane.csv", read);
  EXPECT_EQ(read.illuminance, written.illuminance);
  EXPECT_EQ(read.direct, written.direct);
  EXPECT_EQ(read.sun, written.sun);
  EXPECT_EQ(read.sunReflected, written.sunReflected);
  // The daylight factor columns after the sun's, of E less the sun's light: (1300 − 1000 − 50) /
  // 100 = 2.5 % (direct (1200 − 1000) / 100 = 2 %) and 300 / 100 = 3 % (2 %).
  EXPECT_EQ(read.daylightFactor, (std::vector<double>{2.5, 3.0}));
  EXPECT_EQ(read.daylightFactorDirect, (std::vector<double>{2.0, 2.0}));
  // Without the components given, the direct daylight is written as SC, ERC 0.
  EXPECT_EQ(read.skyComponentFactor, (std::vector<double>{2.0, 2.0}));
  EXPECT_EQ(read.externalComponentFactor, (std::vector<double>{0.0, 0.0}));
}

// The example orientation study: each case's sun is the first case's turned about the vertical by
// the case's north_deg (counter-clockwise seen from above), at the same azimuth and elevation,
// and the study tabulates the sun's metrics after the daylight ones.
TEST(SunInSweeps, TheOrientationStudyTurnsTheSunAboutTheVertical) {
  const Study study = loadStudy(PENUMBRA_SOURCE_DIR "/studies/sun-orientation.yaml");
  const StudyPlan plan = planStudy(study, "kernel", {});
  ASSERT_EQ(plan.layout.cases.size(), 8u);
  const std::vector<StudyMetric> expected{
      StudyMetric::Eavg,    StudyMetric::Emin,    StudyMetric::Emax,    StudyMetric::U0,
      StudyMetric::Ud,      StudyMetric::DFavg,   StudyMetric::DFmin,   StudyMetric::DFmedian,
      StudyMetric::EN17037, StudyMetric::EsunAvg, StudyMetric::EsunMax, StudyMetric::SunlitShare};
  EXPECT_EQ(plan.layout.metrics, expected);
  const Scene first = loadCaseScene(study, plan.layout.cases.front());
  ASSERT_TRUE(first.sun);
  EXPECT_EQ(first.site->northDegrees, 0.0);
  const Vec3 s = first.sun->direction;
  for (const PlannedCase& c : plan.layout.cases) {
    const Scene scene = loadCaseScene(study, c);
    const double north = c.values.front().value * kRadiansPerDegree;
    const Vec3 turned(std::cos(north) * s.x() - std::sin(north) * s.y(),
                      std::sin(north) * s.x() + std::cos(north) * s.y(), s.z());
    EXPECT_TRUE(scene.sun->direction.isApprox(turned, 1e-12))
        << c.id << ": " << scene.sun->direction.transpose() << " vs " << turned.transpose();
    EXPECT_EQ(scene.sun->position.azimuthDegrees, first.sun->position.azimuthDegrees);
    EXPECT_EQ(scene.sun->position.apparentElevationDegrees,
              first.sun->position.apparentElevationDegrees);
  }
}

}  // namespace
}  // namespace penumbra
