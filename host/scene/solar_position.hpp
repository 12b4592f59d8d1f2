#pragma once
// The sun's position in the sky from a date, a clock time and a site, by NOAA's solar calculator
// algorithm (the low-accuracy solar coordinates of Meeus, "Astronomical Algorithms", ch. 25, the
// equation of time of ch. 28, and NOAA's standard-atmosphere refraction). Its error against the
// NREL SPA (Reda & Andreas 2004) is below 0.01° in azimuth and elevation for years 1900–2100
// (tests/solar_position_test.cpp). Universal time is taken for terrestrial time (ΔT ≈ 70 s
// moves the sun by 0.0008°) and the position is geocentric (parallax below 0.0025°).
#include "geometry/vec.hpp"

namespace penumbra {

// A day of the proleptic Gregorian calendar.
struct CivilDate {
  int year = 2000, month = 1, day = 1;  // month 1–12, day 1–31
};

// An instant as the site's clocks give it: a date and the time since its midnight in the site's
// standard time (no daylight saving), `timezoneHours` east of UTC.
struct LocalInstant {
  CivilDate date;
  double secondsOfDay = 0.0;  // s, in [0, 86400)
  double timezoneHours = 0.0;
};

struct GeographicSite {
  double latitudeDegrees = 0.0;   // °, north positive, in [−90, 90]
  double longitudeDegrees = 0.0;  // °, east positive
};

struct SolarPosition {
  double declinationDegrees = 0.0;        // °, apparent
  double equationOfTimeMinutes = 0.0;     // min: true solar time − mean solar time
  double azimuthDegrees = 0.0;            // °, from true north towards east, in [0, 360)
  double elevationDegrees = 0.0;          // °, geometric (no refraction), in [−90, 90]
  double apparentElevationDegrees = 0.0;  // °, with the standard atmosphere's refraction
};

// The Julian day of `instant` (days, UT).
double julianDay(const LocalInstant& instant);

SolarPosition solarPosition(const LocalInstant& instant, const GeographicSite& site);

// The unit vector towards a sun at `azimuthDegrees` (from north towards east) and
// `elevationDegrees`, in the scene's frame: +z up and true north at `northDegrees`
// counter-clockwise from +y seen from above (north_deg 0: north +y, east +x; north_deg 90:
// north −x, east +y).
Vec3 sunDirection(double azimuthDegrees, double elevationDegrees, double northDegrees);

}  // namespace penumbra
