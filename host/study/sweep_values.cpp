#include "study/sweep_values.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

namespace penumbra {
namespace {

using scenefile::Field;
using scenefile::formatNumber;
using scenefile::MapView;
using scenefile::Reader;

// from + k·step is computed, not accumulated, but 1.2 + 3·0.1 is still 1.5000000000000002:
// twelve significant digits give back the 1.5 a person typed, in tables and case folders alike.
double tidy(double value) {
  return std::stod(fmt::format("{:.12g}", value));
}

// `from`, `to` and a third number (`step` or `count`) of a range or a linspace.
struct Interval {
  double from = 0.0, to = 0.0, third = 0.0;
  scenefile::Where thirdWhere;
};

Interval readInterval(const Reader& reader, const Field& field, const std::string& kind,
                      const std::string& third) {
  const MapView map =
      reader.map(field, fmt::format("a {} {{from: .., to: .., {}: ..}}", kind, third));
  map.allowOnly({"from", "to", third}, "a " + kind);
  const Field thirdField = map.require(third);
  return Interval{reader.number(map.require("from")), reader.number(map.require("to")),
                  reader.number(thirdField), thirdField.where};
}

void checkCount(const Reader& reader, const scenefile::Where& where, double count) {
  if (count > static_cast<double>(kMaxSweepValues)) {
    reader.fail(where,
                fmt::format("{:.0f} values are more than the limit of {}", count, kMaxSweepValues));
  }
}

std::vector<double> readRange(const Reader& reader, const Field& field) {
  const Interval range = readInterval(reader, field, "range", "step");
  const double step = range.third;
  const std::string shown = fmt::format("from {} to {} with step {}", formatNumber(range.from),
                                        formatNumber(range.to), formatNumber(step));
  if (step == 0.0) reader.fail(range.thirdWhere, "the step of a range cannot be 0 (" + shown + ")");
  const double steps = (range.to - range.from) / step;
  if (steps < 0.0) {
    reader.fail(field.where, "the range is empty: " + shown +
                                 " never reaches 'to' (use a negative step to count down)");
  }
  // A hair of slack so that 1.0 to 3.0 by 0.1 ends at 3.0 despite rounding.
  const double count = std::floor(steps + 1e-9) + 1.0;
  checkCount(reader, field.where, count);
  std::vector<double> values;
  for (int k = 0; k < static_cast<int>(count); ++k) values.push_back(tidy(range.from + k * step));
  return values;
}

std::vector<double> readLinspace(const Reader& reader, const Field& field) {
  const Interval linspace = readInterval(reader, field, "linspace", "count");
  const double count = linspace.third;
  if (count < 1.0 || count != std::floor(count)) {
    reader.fail(
        linspace.thirdWhere,
        "the count of a linspace is a whole number of at least 1, got " + formatNumber(count));
  }
  checkCount(reader, linspace.thirdWhere, count);
  const int n = static_cast<int>(count);
  std::vector<double> values;
  for (int k = 0; k < n; ++k) {
    // The last value is `to` itself, not from + (n-1)·(to-from)/(n-1).
    values.push_back(k + 1 == n && n > 1 ? linspace.to
                                         : tidy(linspace.from + (linspace.to - linspace.from) * k /
                                                                    std::max(n - 1, 1)));
  }
  return values;
}

std::vector<double> readList(const Reader& reader, const Field& field) {
  std::vector<double> values;
  for (const Field& item : reader.list(field, "a list of values")) {
    values.push_back(reader.number(item));
  }
  if (values.empty()) reader.fail(field.where, "the list of values is empty");
  checkCount(reader, field.where, static_cast<double>(values.size()));
  return values;
}

}  // namespace

std::vector<double> readSweepValues(const Reader& reader, const Field& field) {
  std::vector<double> values;
  if (field.node.IsSequence()) {
    values = readList(reader, field);
  } else {
    const MapView map =
        reader.map(field,
                   "the values of a parameter: [..], {values: [..]}, {range: {from, to, step}} or "
                   "{linspace: {from, to, count}}");
    map.allowOnly({"values", "range", "linspace"}, "a study parameter");
    if (map.entries().size() != 1) {
      reader.fail(field.where,
                  "give the values one way: 'values', 'range' or 'linspace' (exactly one)");
    }
    const MapView::Entry& entry = map.entries().front();
    if (entry.key == "values") values = readList(reader, entry.value);
    if (entry.key == "range") values = readRange(reader, entry.value);
    if (entry.key == "linspace") values = readLinspace(reader, entry.value);
  }
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (values[i] == values[j]) {
        reader.fail(field.where, "the value " + formatNumber(values[i]) +
                                     " is given twice; each value makes one case");
      }
    }
  }
  return values;
}

}  // namespace penumbra
