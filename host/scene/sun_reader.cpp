#include "scene/sun_reader.hpp"

#include <charconv>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::scenefile {
namespace {

// The whole numbers of `text` separated by `separator`, each of `digits[k]` digits; empty when
// the text has another form.
std::vector<int> digitGroups(std::string_view text, char separator,
                             const std::vector<std::size_t>& digits) {
  std::vector<int> groups;
  std::size_t at = 0;
  for (std::size_t k = 0; k < digits.size(); ++k) {
    if (k > 0) {
      if (at >= text.size() || text[at] != separator) return {};
      ++at;
    }
    const std::string_view part = text.substr(at, digits[k]);
    if (part.size() != digits[k]) return {};
    int value = 0;
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (error != std::errc() || end != part.data() + part.size()) return {};
    groups.push_back(value);
    at += digits[k];
  }
  return at == text.size() ? groups : std::vector<int>{};
}

int daysInMonth(int year, int month) {
  static constexpr int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return month == 2 && leap ? 29 : kDays[month - 1];
}

CivilDate readDate(const Reader& reader, const Field& field) {
  const std::string text = reader.text(field);
  const std::vector<int> g = digitGroups(text, '-', {4, 2, 2});
  if (g.empty())
    reader.fail(field.where, "a date is written YYYY-MM-DD (2026-03-21), got '" + text + "'");
  const CivilDate date{g[0], g[1], g[2]};
  if (date.month < 1 || date.month > 12 || date.day < 1 ||
      date.day > daysInMonth(date.year, date.month))
    reader.fail(field.where, "'" + text + "' is not a day of the calendar");
  return date;
}

double readTimeOfDay(const Reader& reader, const Field& field) {
  const std::string text = reader.text(field);
  std::vector<int> g = digitGroups(text, ':', {2, 2});
  if (g.empty()) g = digitGroups(text, ':', {2, 2, 2});
  if (g.empty())
    reader.fail(
        field.where,
        "a time of day is written \"HH:MM\" or \"HH:MM:SS\" (\"10:00\"), got '" + text + "'");
  if (g.size() == 2) g.push_back(0);
  if (g[0] > 23 || g[1] > 59 || g[2] > 59)
    reader.fail(field.where, "'" + text + "' is not a time of day (00:00 to 23:59:59)");
  return g[0] * 3600.0 + g[1] * 60.0 + g[2];
}

}  // namespace

SunSpec readSun(const Reader& reader, const Field& field) {
  const MapView map = reader.map(field, "the sun");
  map.allowOnly({"date", "time", "direct_normal_illuminance_lx"}, "the sun");
  SunSpec sun;
  sun.where = field.where;
  sun.date = readDate(reader, map.require("date"));
  sun.secondsOfDay = readTimeOfDay(reader, map.require("time"));
  sun.directNormalIlluminance = reader.positive(map.require("direct_normal_illuminance_lx"), "lx");
  return sun;
}

Sun placeSun(const SunSpec& spec, const std::optional<Site>& site, const BuildContext& context) {
  if (!site)
    context.fail(spec.where,
                 "the sun's position needs the site: add 'site: {latitude_deg: .., "
                 "longitude_deg: .., timezone_h: ..}'");
  Sun sun;
  sun.instant = LocalInstant{spec.date, spec.secondsOfDay, site->timezoneHours};
  sun.directNormalIlluminance = spec.directNormalIlluminance;
  sun.position = solarPosition(sun.instant, {site->latitudeDegrees, site->longitudeDegrees});
  sun.direction = sunDirection(sun.position.azimuthDegrees, sun.position.apparentElevationDegrees,
                               site->northDegrees);
  return sun;
}

}  // namespace penumbra::scenefile
