#include "photometry/ies_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "photometry/ies_number_stream.hpp"
#include "photometry/luminous_opening.hpp"
#include "photometry/photometric_error.hpp"
#include "photometry/photometric_text.hpp"

namespace penumbra::photometry {
namespace {

std::string upper(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

// "IESNA:LM-63-2002" -> "LM-63-2002"; "IESNA91" -> "LM-63-1991"; a first line that does not start
// with "IES" is LM-63-1986's first label line (empty result).
std::string versionOf(std::string_view firstLine, std::vector<std::string>& warnings) {
  const std::string line = upper(trim(firstLine));
  if (line.rfind("IES", 0) != 0) return "";
  for (const char* year : {"2019", "2002", "1995"}) {
    if (line.find(std::string("LM-63-") + year) != std::string::npos) {
      return std::string("LM-63-") + year;
    }
  }
  if (line.rfind("IESNA91", 0) == 0) return "LM-63-1991";
  warnings.push_back(
      fmt::format("unknown version line {}: read as LM-63-2002", quoteForMessage(trim(firstLine))));
  return "LM-63-2002";
}

struct Header {
  std::string tilt;           // what follows "TILT=", trimmed, upper case
  int tiltLine = 0;           // 1-based
  std::size_t dataStart = 0;  // offset of the line after TILT
};

// The keyword (or label) lines up to TILT=.
Header readHeader(std::string_view text, const std::vector<std::string_view>& lines,
                  const std::filesystem::path& file, PhotometricData& data) {
  std::size_t first = 0;
  data.version = versionOf(lines[0], data.warnings);
  if (data.version.empty()) {
    data.version = "LM-63-1986";
  } else {
    first = 1;
  }
  for (std::size_t i = first; i < lines.size(); ++i) {
    const int lineNumber = static_cast<int>(i) + 1;
    const std::string_view line = trim(lines[i]);
    if (upper(line.substr(0, 4)) == "TILT") {
      const std::size_t equals = line.find('=');
      if (equals == std::string_view::npos || trim(line.substr(4, equals - 4)).size() != 0) {
        throw PhotometricError(
            file, lineNumber, "TILT",
            "expected TILT=NONE, TILT=INCLUDE or TILT=<file>, found " + quoteForMessage(line));
      }
      Header header;
      header.tilt = std::string(trim(line.substr(equals + 1)));
      header.tiltLine = lineNumber;
      header.dataStart = static_cast<std::size_t>(lines[i].data() - text.data()) + lines[i].size();
      return header;
    }
    if (!line.empty() && line.front() == '[') {
      const std::size_t close = line.find(']');
      if (close == std::string_view::npos) {
        data.warnings.push_back(fmt::format("line {}: keyword without ']'", lineNumber));
        data.header.push_back({"", std::string(line), lineNumber});
        continue;
      }
      const std::string name = upper(line.substr(1, close - 1));
      const std::string value(trim(line.substr(close + 1)));
      if (name == "MORE" && !data.header.empty()) {
        data.header.back().value += "\n" + value;
      } else {
        data.header.push_back({name, value, lineNumber});
      }
    } else if (!line.empty()) {
      if (data.version != "LM-63-1986") {
        data.warnings.push_back(
            fmt::format("line {}: text that is not a [KEYWORD] line", lineNumber));
      }
      data.header.push_back({"", std::string(line), lineNumber});
    }
  }
  throw PhotometricError(file, static_cast<int>(lines.size()), "TILT",
                         "no TILT= line: the file ends after its keyword lines");
}

void readTilt(IesNumberStream& numbers, PhotometricData& data) {
  TiltTable tilt;
  tilt.lampToLuminaireGeometry =
      numbers.integer("lamp-to-luminaire geometry", 1, 3, "1 vertical, 2 or 3 horizontal");
  const int count = numbers.integer("number of tilt angles", 1, 1801, "at most 1801");
  const NumberedValues angles = numbers.values("tilt angles", static_cast<std::size_t>(count));
  checkAngles(angles, numbers.file(), "tilt angles", -180, 180);
  const NumberedValues factors =
      numbers.values("tilt multiplying factors", static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < factors.values.size(); ++i) {
    candelaOf(factors.values[i], 1, factors.lines[i], numbers.file(), "tilt multiplying factors",
              fmt::format("tilt angle {}°", angles.values[i]));
  }
  tilt.anglesDeg = angles.values;
  tilt.factors = factors.values;
  data.tilt = std::move(tilt);
}

// The symmetry LM-63 reads from the first and last horizontal angles.
HorizontalSymmetry symmetryOf(const NumberedValues& h, PhotometricType type,
                              const std::filesystem::path& file) {
  const double first = h.values.front(), last = h.values.back();
  const char* field = "horizontal angles";
  if (type != PhotometricType::C) {
    if (first == 0) return HorizontalSymmetry::Lateral;
    if (first < 0) return HorizontalSymmetry::None;
    throw PhotometricError(file, h.lines.front(), field,
                           fmt::format("type A and B tables start at 0° (laterally symmetric) or "
                                       "below, not at {}°",
                                       first));
  }
  if (first == 0) {
    if (h.values.size() == 1) return HorizontalSymmetry::Rotational;
    if (last == 90) return HorizontalSymmetry::Quadrant;
    if (last == 180) return HorizontalSymmetry::AboutC0C180;
    if (last > 180) return HorizontalSymmetry::None;
  } else if (first == 90 && last == 270) {
    return HorizontalSymmetry::AboutC90C270;
  } else if (first != 90) {
    throw PhotometricError(file, h.lines.front(), field,
                           fmt::format("type C tables start at 0° (or 90° for a 90-270° table), "
                                       "not at {}°",
                                       first));
  }
  throw PhotometricError(
      file, h.lines.back(), field,
      fmt::format("a table from {}° to {}° has no LM-63 symmetry: type C tables run 0, 0-90, "
                  "0-180, 0-360 (last above 180) or 90-270",
                  first, last));
}

// [_LOR] (light output ratio in %), which LM-63 itself does not define.
void readLightOutputRatio(const std::filesystem::path& file, PhotometricData& data) {
  for (const HeaderField& field : data.header) {
    if (field.name != "_LOR") continue;
    const auto value = parseNumber(trim(field.value));
    if (!value || *value <= 0 || *value > 100) {
      throw PhotometricError(file, field.line, "[_LOR]",
                             "expected the light output ratio in % (above 0, at most 100), found " +
                                 quoteForMessage(field.value));
    }
    data.lightOutputRatio = *value / 100;
  }
}

}  // namespace

PhotometricData parseIes(std::string_view text, const std::filesystem::path& file) {
  text = withoutByteOrderMark(text);
  PhotometricData data;
  data.format = PhotometricFormat::Ies;
  const std::vector<std::string_view> lines = splitLines(text);
  if (trim(text).empty()) throw PhotometricError(file, 1, "IES file", "the file is empty");
  const Header header = readHeader(text, lines, file, data);
  readLightOutputRatio(file, data);

  const int lastLine = static_cast<int>(lines.size());
  IesNumberStream numbers(text.substr(std::min(header.dataStart, text.size())), header.tiltLine,
                          lastLine, file);
  const std::string tilt = upper(header.tilt);
  if (tilt == "INCLUDE") {
    readTilt(numbers, data);
  } else if (tilt != "NONE") {
    throw PhotometricError(file, header.tiltLine, "TILT",
                           "tilt file " + quoteForMessage(header.tilt) +
                               " is not read: put the tilt table in the file (TILT=INCLUDE)");
  }

  const int lamps = numbers.integer("number of lamps", 1, 1000);
  const double lumensPerLamp = numbers.number("lumens per lamp");
  const int lumensLine = numbers.line();
  if (lumensPerLamp == -1) {
    data.absolutePhotometry = true;
  } else if (!(lumensPerLamp > 0)) {
    throw PhotometricError(file, lumensLine, "lumens per lamp",
                           fmt::format("{} lm: expected a positive value, or -1 for absolute "
                                       "photometry",
                                       lumensPerLamp));
  }
  const double multiplier = numbers.number("candela multiplier");
  if (!(multiplier > 0)) {
    throw PhotometricError(file, numbers.line(), "candela multiplier",
                           fmt::format("{}: expected a positive factor", multiplier));
  }
  const int nVertical = numbers.integer("number of vertical angles", 1, kMaxIesVerticalAngles,
                                        "at most 1801: 0.1° steps over 180°");
  const int nHorizontal = numbers.integer("number of horizontal angles", 1, kMaxIesHorizontalAngles,
                                          "at most 3601: 0.1° steps over 360°");
  const int type = numbers.integer("photometric type", 1, 3, "1 = C, 2 = B, 3 = A");
  data.type =
      type == 1 ? PhotometricType::C : (type == 2 ? PhotometricType::B : PhotometricType::A);
  const int units = numbers.integer("units type", 1, 2, "1 = feet, 2 = metres");
  SignedOpening dimensions;
  dimensions.width = numbers.number("luminous opening width");
  dimensions.length = numbers.number("luminous opening length");
  dimensions.height = numbers.number("luminous opening height");
  const int openingLine = numbers.line();
  const auto opening = openingFromIes(dimensions, units == 1 ? 0.3048 : 1.0);
  if (opening) {
    data.opening = *opening;
  } else {
    data.warnings.push_back(fmt::format(
        "line {}: luminous opening {} {} {}: a sign combination LM-63 does not define; read as a "
        "point",
        openingLine, dimensions.width, dimensions.length, dimensions.height));
  }
  const double ballastFactor = numbers.number("ballast factor");
  if (!(ballastFactor > 0)) {
    throw PhotometricError(file, numbers.line(), "ballast factor",
                           fmt::format("{}: expected a positive factor", ballastFactor));
  }
  // The third factor: LM-63-1995 and before the ballast-lamp photometric factor, 2002 "future
  // use", 2019 the file generation type. Only the first multiplies the candela.
  const bool oldFactor = data.version <= "LM-63-1995";
  const std::string thirdField =
      oldFactor ? "ballast-lamp photometric factor"
                : (data.version == "LM-63-2019" ? "file generation type" : "future use");
  const double third = numbers.number(thirdField);
  if (oldFactor && !(third > 0)) {
    throw PhotometricError(file, numbers.line(), thirdField,
                           fmt::format("{}: expected a positive factor", third));
  }
  data.inputWatts = numbers.number("input watts");
  if (data.inputWatts < 0) {
    throw PhotometricError(file, numbers.line(), "input watts",
                           fmt::format("{} W: must not be negative", data.inputWatts));
  }

  const NumberedValues vertical =
      numbers.values("vertical angles", static_cast<std::size_t>(nVertical));
  const NumberedValues horizontal =
      numbers.values("horizontal angles", static_cast<std::size_t>(nHorizontal));
  const bool typeC = data.type == PhotometricType::C;
  // Type B: V is the plane about the horizontal polar axis, H the angle in it; type A the reverse
  // (docs/photometry.md).
  checkAngles(vertical, file, "vertical angles", typeC ? 0 : (type == 2 ? -180 : -90),
              typeC ? 180 : (type == 2 ? 180 : 90));
  checkAngles(horizontal, file, "horizontal angles", typeC ? 0 : (type == 2 ? -90 : -180),
              typeC ? 360 : (type == 2 ? 90 : 180));
  data.symmetry = symmetryOf(horizontal, data.type, file);
  data.verticalAnglesDeg = vertical.values;
  data.horizontalAnglesDeg = horizontal.values;

  const double factor = multiplier * ballastFactor * (oldFactor ? third : 1.0);
  // Each value takes two characters at least: a file cannot hold more than that, whatever its
  // counts declare.
  data.candela.reserve(
      std::min(static_cast<std::size_t>(nVertical) * static_cast<std::size_t>(nHorizontal),
               text.size() / 2 + 1));
  for (int h = 0; h < nHorizontal; ++h) {
    const std::string field = fmt::format("candela values (horizontal angle {}°)",
                                          horizontal.values[static_cast<std::size_t>(h)]);
    const NumberedValues row = numbers.values(field, static_cast<std::size_t>(nVertical));
    for (std::size_t v = 0; v < row.values.size(); ++v) {
      const std::string where = fmt::format("vertical angle {}°", vertical.values[v]);
      const double cd = candelaOf(row.values[v], factor, row.lines[v], file, field, where);
      data.candela.push_back(cd);
    }
  }
  if (data.symmetry == HorizontalSymmetry::None && data.type == PhotometricType::C &&
      horizontal.values.back() == 360 &&
      !std::equal(data.candela.begin(), data.candela.begin() + nVertical,
                  data.candela.end() - nVertical)) {
    data.warnings.push_back("the planes at 0° and 360° differ; the one at 0° is used for both");
  }
  int extraLine = 0;
  const std::size_t extra = numbers.wordsLeft(extraLine);
  if (extra > 0) {
    throw PhotometricError(
        file, extraLine, "candela values",
        fmt::format("{} more values after the {} x {} table: the numbers of angles do not match "
                    "the data",
                    extra, nHorizontal, nVertical));
  }

  LampSet lampSet;
  lampSet.count = lamps;
  lampSet.lumens = data.absolutePhotometry ? 0 : lamps * lumensPerLamp;
  lampSet.watts = data.inputWatts;
  for (const HeaderField& field : data.header) {
    if (field.name == "LAMP") lampSet.type = field.value;
  }
  data.lampLumens = lampSet.lumens;
  data.lamps.push_back(lampSet);
  return data;
}

}  // namespace penumbra::photometry
