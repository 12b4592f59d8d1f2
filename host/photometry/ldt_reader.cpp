#include "photometry/ldt_reader.hpp"

#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "photometry/field_checks.hpp"
#include "photometry/luminous_opening.hpp"
#include "photometry/photometric_error.hpp"
#include "photometry/photometric_text.hpp"

namespace penumbra::photometry {
namespace {

// The file's lines, read in order: each read names its field and errors at its line.
class LdtLines {
 public:
  LdtLines(std::string_view text, std::filesystem::path file)
      : lines_(splitLines(text)), file_(std::move(file)) {}

  int line() const { return next_; }  // 1-based line of the field read last

  std::string text(const std::string& field) {
    if (next_ >= static_cast<int>(lines_.size())) {
      throw PhotometricError(file_, static_cast<int>(lines_.size()), field,
                             fmt::format("missing: the file ends before line {}", next_ + 1));
    }
    return std::string(trim(lines_[static_cast<std::size_t>(next_++)]));
  }

  double number(const std::string& field) {
    const std::string word = text(field);
    const auto value = parseNumber(word, true);
    if (!value) {
      throw PhotometricError(file_, next_, field,
                             "expected a number, found " + quoteForMessage(word));
    }
    return *value;
  }

  // A whole number in [min, max].
  int integer(const std::string& field, int min, int max, const std::string& meaning = "") {
    const double value = number(field);
    return wholeNumber(value, min, max, meaning, file_, next_, field);
  }

  // A number in [min, max].
  double within(const std::string& field, double min, double max, const std::string& unit) {
    const double value = number(field);
    if (value < min || value > max) {
      throw PhotometricError(
          file_, next_, field,
          fmt::format("{} {} is outside {} to {} {}", value, unit, min, max, unit));
    }
    return value;
  }

  NumberedValues numbers(const std::string& field, std::size_t count) {
    NumberedValues out;
    for (std::size_t i = 0; i < count; ++i) {
      if (next_ >= static_cast<int>(lines_.size())) {
        throw PhotometricError(
            file_, static_cast<int>(lines_.size()), field,
            fmt::format("expected {} values, found {} (the file ends)", count, i));
      }
      out.values.push_back(number(field));
      out.lines.push_back(next_);
    }
    return out;
  }

  // The first line after the table that holds anything, or 0.
  int firstNonEmptyLineLeft() const {
    for (std::size_t i = static_cast<std::size_t>(next_); i < lines_.size(); ++i) {
      if (!trim(lines_[i]).empty()) return static_cast<int>(i) + 1;
    }
    return 0;
  }

  const std::filesystem::path& file() const { return file_; }

 private:
  std::vector<std::string_view> lines_;
  std::filesystem::path file_;
  int next_ = 0;  // index of the next line
};

// The first and one past the last stored C plane (0-based) for Isym, from the EULUMDAT
// specification; Isym 3 stores C90-C270.
struct StoredPlanes {
  int first;
  int end;
};

StoredPlanes storedPlanes(int isym, int mc) {
  switch (isym) {
    case 1:
      return {0, 1};
    case 2:
      return {0, mc / 2 + 1};
    case 3:
      return {mc / 4, 3 * mc / 4 + 1};
    case 4:
      return {0, mc / 4 + 1};
    default:
      return {0, mc};
  }
}

HorizontalSymmetry symmetryOf(int isym) {
  switch (isym) {
    case 1:
      return HorizontalSymmetry::Rotational;
    case 2:
      return HorizontalSymmetry::AboutC0C180;
    case 3:
      return HorizontalSymmetry::AboutC90C270;
    case 4:
      return HorizontalSymmetry::Quadrant;
    default:
      return HorizontalSymmetry::None;
  }
}

// The C plane at `index` must lie at `expected` degrees for the symmetry to close.
void expectPlaneAt(const NumberedValues& c, int index, double expected, int isym,
                   const std::filesystem::path& file) {
  const double actual = c.values[static_cast<std::size_t>(index)];
  if (actual != expected) {
    throw PhotometricError(file, c.lines[static_cast<std::size_t>(index)], "C angles",
                           fmt::format("plane {} is at {}°; with Isym {} it must be at {}°",
                                       index + 1, actual, isym, expected));
  }
}

// The lamp sets: n, then per set its six lines (26a-26f of the EULUMDAT specification): number
// of lamps, type, total flux (lm), colour temperature, colour rendering, wattage (W).
void readLampSets(LdtLines& in, PhotometricData& data) {
  const int sets = in.integer("number of lamp sets", 1, kMaxLdtLampSets, "at most 100");
  data.lamps.resize(static_cast<std::size_t>(sets));
  for (int i = 0; i < sets; ++i) {
    LampSet& set = data.lamps[static_cast<std::size_t>(i)];
    const auto field = [i](const char* name) { return fmt::format("{} (set {})", name, i + 1); };
    set.count = in.integer(field("number of lamps"), -100000, 100000);
    if (set.count == 0) {
      throw PhotometricError(in.file(), in.line(), field("number of lamps"), "must not be 0");
    }
    if (set.count < 0) data.absolutePhotometry = true;
    set.type = in.text(field("lamp type"));
    set.lumens = in.number(field("lamp luminous flux"));
    if (!(set.lumens > 0)) {
      throw PhotometricError(in.file(), in.line(), field("lamp luminous flux"),
                             fmt::format("{} lm: expected a positive flux", set.lumens));
    }
    data.lampLumens += set.lumens;
    set.colour = in.text(field("colour temperature"));
    set.renderingIndex = in.text(field("colour rendering index"));
    set.watts = in.within(field("wattage"), 0, 1e7, "W");
    data.inputWatts += set.watts;
  }
}

}  // namespace

PhotometricData parseLdt(std::string_view text, const std::filesystem::path& file) {
  text = withoutByteOrderMark(text);
  if (trim(text).empty()) throw PhotometricError(file, 1, "EULUMDAT file", "the file is empty");
  PhotometricData data;
  data.format = PhotometricFormat::Eulumdat;
  data.version = "EULUMDAT";
  data.type = PhotometricType::C;
  LdtLines in(text, file);
  const auto keep = [&](const std::string& name, const std::string& value) {
    data.header.push_back({name, value, in.line()});
  };
  keep("company/database/version", in.text("company identification"));
  const int ityp = in.integer("type indicator Ityp", 0, 3,
                              "0 point source, 1 rotationally symmetric, 2 linear, 3 other");
  keep("type indicator Ityp", std::to_string(ityp));
  const int isym = in.integer("symmetry indicator Isym", 0, 4);
  const int mc = in.integer("number of C planes Mc", 1, kMaxLdtCPlanes, "at most 3600");
  if ((isym == 2 && mc % 2 != 0) || ((isym == 3 || isym == 4) && mc % 4 != 0)) {
    throw PhotometricError(file, in.line(), "number of C planes Mc",
                           fmt::format("{} planes cannot be split as Isym {} requires (a "
                                       "multiple of {})",
                                       mc, isym, isym == 2 ? 2 : 4));
  }
  keep("distance between C planes Dc (deg)", fmt::format("{}", in.number("Dc")));
  const int ng = in.integer("number of γ angles Ng", 1, kMaxLdtGammaAngles, "at most 1801");
  keep("distance between γ angles Dg (deg)", fmt::format("{}", in.number("Dg")));
  keep("measurement report number", in.text("measurement report number"));
  keep("luminaire name", in.text("luminaire name"));
  keep("luminaire number", in.text("luminaire number"));
  keep("file name", in.text("file name"));
  keep("date/user", in.text("date/user"));
  keep("luminaire length/diameter (mm)",
       fmt::format("{}", in.within("luminaire length", 0, 1e6, "mm")));
  keep("luminaire width (mm)", fmt::format("{}", in.within("luminaire width", 0, 1e6, "mm")));
  keep("luminaire height (mm)", fmt::format("{}", in.within("luminaire height", 0, 1e6, "mm")));
  const double areaLength = in.within("luminous area length", 0, 1e6, "mm");
  const double areaWidth = in.within("luminous area width", 0, 1e6, "mm");
  double heights[4];
  const char* planes[4] = {"C0", "C90", "C180", "C270"};
  for (int i = 0; i < 4; ++i) {
    heights[i] = in.within(fmt::format("luminous area height {}", planes[i]), 0, 1e6, "mm");
  }
  data.opening = openingFromEulumdat(areaLength, areaWidth, heights);
  keep("downward flux fraction DFF (%)", fmt::format("{}", in.within("DFF", 0, 100, "%")));
  data.lightOutputRatio = in.within("light output ratio LORL", 0, 100, "%") / 100;
  const double conversion = in.number("conversion factor CFLI");
  if (!(conversion > 0)) {
    throw PhotometricError(file, in.line(), "conversion factor CFLI",
                           fmt::format("{}: expected a positive factor", conversion));
  }
  keep("tilt during measurement (deg)",
       fmt::format("{}", in.within("tilt during measurement", -180, 180, "°")));
  readLampSets(in, data);
  for (int i = 0; i < 10; ++i) {
    keep(fmt::format("direct ratio k{}", i + 1),
         fmt::format("{}", in.number(fmt::format("direct ratio {} of 10", i + 1))));
  }
  const NumberedValues c = in.numbers("C angles", static_cast<std::size_t>(mc));
  checkAngles(c, file, "C angles", 0, 360);
  if (isym != 1 && c.values.front() != 0) expectPlaneAt(c, 0, 0, isym, file);
  if (isym == 2) expectPlaneAt(c, mc / 2, 180, isym, file);
  if (isym == 3) {
    expectPlaneAt(c, mc / 4, 90, isym, file);
    expectPlaneAt(c, 3 * mc / 4, 270, isym, file);
  }
  if (isym == 4) expectPlaneAt(c, mc / 4, 90, isym, file);
  if (isym == 0 && c.values.back() >= 360) {
    throw PhotometricError(file, c.lines.back(), "C angles",
                           "with Isym 0 the planes run from 0° to below 360° (360° is C0)");
  }
  const NumberedValues g = in.numbers("γ angles", static_cast<std::size_t>(ng));
  checkAngles(g, file, "γ angles", 0, 180);

  const StoredPlanes stored = storedPlanes(isym, mc);
  data.symmetry = symmetryOf(isym);
  data.horizontalAnglesDeg.assign(c.values.begin() + stored.first, c.values.begin() + stored.end);
  data.verticalAnglesDeg = g.values;
  const double cdPerValue = conversion * data.lampLumens / 1000;
  for (int p = stored.first; p < stored.end; ++p) {
    const std::string field =
        fmt::format("luminous intensities (C {}°)", c.values[static_cast<std::size_t>(p)]);
    const NumberedValues row = in.numbers(field, static_cast<std::size_t>(ng));
    for (std::size_t v = 0; v < row.values.size(); ++v) {
      const double cd = candelaOf(row.values[v], cdPerValue, row.lines[v], file, field,
                                  fmt::format("γ {}° (cd/klm)", g.values[v]));
      data.candela.push_back(cd);
    }
  }
  if (const int extra = in.firstNonEmptyLineLeft(); extra > 0) {
    throw PhotometricError(
        file, extra, "luminous intensities",
        fmt::format("more lines after the {} x {} values that Mc = {}, Ng = {} and Isym = {} "
                    "call for: the counts do not match the data",
                    stored.end - stored.first, ng, mc, ng, isym));
  }
  return data;
}

}  // namespace penumbra::photometry
