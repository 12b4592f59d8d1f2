#include "scene/solar_position.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/angles.hpp"

namespace penumbra {

namespace {

double sinDegrees(double a) {
  return std::sin(a * kRadiansPerDegree);
}
double cosDegrees(double a) {
  return std::cos(a * kRadiansPerDegree);
}

// NOAA's refraction (°) of a sun at geometric elevation `e` (°): Saemundsson-type series above
// 5°, a polynomial fit to the standard atmosphere between −0.575° and 5°, none above 85°.
double refractionDegrees(double e) {
  if (e > 85.0) return 0.0;
  const double t = std::tan(e * kRadiansPerDegree);
  double arcseconds = 0.0;
  if (e > 5.0) {
    arcseconds = 58.1 / t - 0.07 / (t * t * t) + 0.000086 / std::pow(t, 5);
  } else if (e > -0.575) {
    arcseconds = 1735.0 + e * (-518.2 + e * (103.4 + e * (-12.79 + e * 0.711)));
  } else {
    arcseconds = -20.772 / t;
  }
  return arcseconds / 3600.0;
}

}  // namespace

double julianDay(const LocalInstant& instant) {
  // Meeus ch. 7, Gregorian calendar.
  int y = instant.date.year, m = instant.date.month;
  if (m <= 2) {
    y -= 1;
    m += 12;
  }
  const int a = static_cast<int>(std::floor(y / 100.0));
  const int b = 2 - a + static_cast<int>(std::floor(a / 4.0));
  const double midnight = std::floor(365.25 * (y + 4716)) + std::floor(30.6001 * (m + 1)) +
                          instant.date.day + b - 1524.5;
  return midnight + instant.secondsOfDay / 86400.0 - instant.timezoneHours / 24.0;
}

SolarPosition solarPosition(const LocalInstant& instant, const GeographicSite& site) {
  const double t = (julianDay(instant) - 2451545.0) / 36525.0;  // Julian centuries from J2000
  const double meanLongitude = std::fmod(280.46646 + t * (36000.76983 + t * 0.0003032), 360.0);
  const double meanAnomaly = 357.52911 + t * (35999.05029 - 0.0001537 * t);
  const double eccentricity = 0.016708634 - t * (0.000042037 + 0.0000001267 * t);
  const double centre = sinDegrees(meanAnomaly) * (1.914602 - t * (0.004817 + 0.000014 * t)) +
                        sinDegrees(2.0 * meanAnomaly) * (0.019993 - 0.000101 * t) +
                        sinDegrees(3.0 * meanAnomaly) * 0.000289;
  const double trueLongitude = meanLongitude + centre;
  const double node = 125.04 - 1934.136 * t;
  const double apparentLongitude = trueLongitude - 0.00569 - 0.00478 * sinDegrees(node);
  const double meanObliquity =
      23.0 + (26.0 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0;
  const double obliquity = meanObliquity + 0.00256 * cosDegrees(node);

  SolarPosition p;
  const double declination =
      std::asin(sinDegrees(obliquity) * sinDegrees(apparentLongitude));  // rad
  p.declinationDegrees = declination * kDegreesPerRadian;
  const double y = std::pow(std::tan(obliquity * kRadiansPerDegree / 2.0), 2);
  const double l0 = meanLongitude * kRadiansPerDegree, m = meanAnomaly * kRadiansPerDegree;
  const double e = eccentricity;
  p.equationOfTimeMinutes = 4.0 * kDegreesPerRadian *
                            (y * std::sin(2.0 * l0) - 2.0 * e * std::sin(m) +
                             4.0 * e * y * std::sin(m) * std::cos(2.0 * l0) -
                             0.5 * y * y * std::sin(4.0 * l0) - 1.25 * e * e * std::sin(2.0 * m));

  // True solar time (min) and the hour angle (°, 0 at solar noon, positive in the afternoon).
  const double clockMinutes = instant.secondsOfDay / 60.0;
  const double solarMinutes = clockMinutes + p.equationOfTimeMinutes + 4.0 * site.longitudeDegrees -
                              60.0 * instant.timezoneHours;
  const double hourAngle = (solarMinutes / 4.0 - 180.0) * kRadiansPerDegree;
  const double latitude = site.latitudeDegrees * kRadiansPerDegree;

  const double sinElevation = std::sin(latitude) * std::sin(declination) +
                              std::cos(latitude) * std::cos(declination) * std::cos(hourAngle);
  p.elevationDegrees = std::asin(std::clamp(sinElevation, -1.0, 1.0)) * kDegreesPerRadian;
  // Azimuth from north towards east: west of the meridian in the afternoon (hour angle > 0).
  const double azimuth =
      std::atan2(-std::sin(hourAngle) * std::cos(declination),
                 std::sin(declination) * std::cos(latitude) -
                     std::cos(declination) * std::sin(latitude) * std::cos(hourAngle));
  p.azimuthDegrees = std::fmod(azimuth * kDegreesPerRadian + 360.0, 360.0);
  p.apparentElevationDegrees = p.elevationDegrees + refractionDegrees(p.elevationDegrees);
  return p;
}

Vec3 sunDirection(double azimuthDegrees, double elevationDegrees, double northDegrees) {
  const Vec3 north(-sinDegrees(northDegrees), cosDegrees(northDegrees), 0.0);
  const Vec3 east(cosDegrees(northDegrees), sinDegrees(northDegrees), 0.0);
  const double horizontal = cosDegrees(elevationDegrees);
  return (horizontal * (sinDegrees(azimuthDegrees) * east + cosDegrees(azimuthDegrees) * north) +
          sinDegrees(elevationDegrees) * Vec3::UnitZ())
      .normalized();
}

}  // namespace penumbra
