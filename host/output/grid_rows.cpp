#include "output/grid_rows.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <iterator>

namespace penumbra {

void GridRows::add(const Vec3& position, const Vec3& normal, double illuminance,
                   std::string_view insideField) {
  addRow(position, normal, GridRowValues{illuminance, nullptr, 0.0}, insideField);
}

void GridRows::add(const Vec3& position, const Vec3& normal, double illuminance, double direct,
                   std::string_view insideField) {
  addRow(position, normal, GridRowValues{illuminance, &direct, 0.0}, insideField);
}

void GridRows::add(const Vec3& position, const Vec3& normal, const GridRowValues& values,
                   std::string_view insideField) {
  addRow(position, normal, values, insideField);
}

void GridRows::addRow(const Vec3& position, const Vec3& normal, const GridRowValues& values,
                      std::string_view insideField) {
  const double illuminance = values.illuminance;
  const double* direct = values.direct;
  // Room for the most numbers a row holds (6 for the point, 3 for E and its parts, 2 for the
  // sun, 6 for the daylight factor) and their separators, the field and the line break; the
  // buffer is then cut to what was written (fmt's resize leaves new bytes unset).
  const std::size_t start = csv_.size();
  csv_.resize(start + 17 * (kMaxNumberText + 1) + insideField.size() + 1);
  char* out = writePoint(csv_.data() + start, position, normal, ',');
  const char* e = out;
  // The .pts line: the same six numbers, blank-separated: x's text, then the tail's blank form.
  const std::size_t ptsStart = pts_.size();
  const auto pointSize = static_cast<std::size_t>(e - (csv_.data() + start));
  const std::size_t xSize = pointSize - tailSize_;
  pts_.resize(ptsStart + pointSize);
  char* point = pts_.data() + ptsStart;
  std::memcpy(point, csv_.data() + start, xSize);
  point[xSize - 1] = ' ';
  std::memcpy(point + xSize, tailBlankText_, tailSize_);
  point[pointSize - 1] = '\n';
  out = writeNumber(out, illuminance, illuminanceDigits_);  // E hardly ever repeats: not looked up
  const auto eSize = static_cast<std::size_t>(out - e);
  addResLine(e, eSize);
  *out++ = ',';
  if (direct != nullptr) {
    out = writeNumber(out, *direct, illuminanceDigits_);
    *out++ = ',';
    out = writeNumber(out, illuminance - *direct, illuminanceDigits_);
    *out++ = ',';
  }
  const double sun = sunColumn_ ? values.sun : 0.0;
  const double sunReflected = sunColumn_ && direct != nullptr ? values.sunReflected : 0.0;
  if (sunColumn_) {
    out = writeNumber(out, sun, illuminanceDigits_);
    *out++ = ',';
    if (direct != nullptr) {
      out = writeNumber(out, sunReflected, illuminanceDigits_);
      *out++ = ',';
    }
  }
  if (outdoor_ > 0.0) {
    const double toPercent = 100.0 / outdoor_;
    const double daylight = illuminance - sun - sunReflected;
    out = writeNumber(out, toPercent * daylight);
    *out++ = ',';
    if (direct != nullptr) {
      out = writeNumber(out, toPercent * (*direct - sun));
      *out++ = ',';
      out = writeNumber(out, toPercent * daylight - toPercent * (*direct - sun));
      *out++ = ',';
      const double sky = values.skyComponent ? *values.skyComponent : *direct - sun;
      const double external = values.externalComponent ? *values.externalComponent : 0.0;
      out = writeNumber(out, toPercent * sky);
      *out++ = ',';
      out = writeNumber(out, toPercent * external);
      *out++ = ',';
      out = writeNumber(out, toPercent * daylight - toPercent * sky - toPercent * external);
      *out++ = ',';
    }
  }
  if (!insideField.empty()) std::memcpy(out, insideField.data(), insideField.size());
  out += insideField.size();
  *out++ = '\n';
  csv_.resize(static_cast<std::size_t>(out - csv_.data()));
}

void GridRows::addPoint(const Vec3& position, const Vec3& normal) {
  const std::size_t start = pts_.size();
  pts_.resize(start + 6 * (kMaxNumberText + 1));
  char* end = writePoint(pts_.data() + start, position, normal, ' ');
  end[-1] = '\n';
  pts_.resize(static_cast<std::size_t>(end - pts_.data()));
}

char* GridRows::writePoint(char* out, const Vec3& position, const Vec3& normal, char separator) {
  out = numbers_.write(out, position.x());
  *out++ = separator;
  const std::uint64_t bits[5] = {
      std::bit_cast<std::uint64_t>(position.y()), std::bit_cast<std::uint64_t>(position.z()),
      std::bit_cast<std::uint64_t>(normal.x()), std::bit_cast<std::uint64_t>(normal.y()),
      std::bit_cast<std::uint64_t>(normal.z())};
  if (tailSize_ > 0 && separator == tailSeparator_ &&
      std::equal(std::begin(bits), std::end(bits), std::begin(tailBits_))) {
    std::memcpy(out, tailText_, tailSize_);
    return out + tailSize_;
  }
  char* const tail = out;
  for (const double value : {position.y(), position.z(), normal.x(), normal.y(), normal.z()}) {
    out = numbers_.write(out, value);
    *out++ = separator;
  }
  tailSize_ = static_cast<std::size_t>(out - tail);
  std::memcpy(tailText_, tail, tailSize_);
  std::replace_copy(tail, out, tailBlankText_, separator, ' ');
  std::copy(std::begin(bits), std::end(bits), std::begin(tailBits_));
  tailSeparator_ = separator;
  return out;
}

void GridRows::addIlluminance(double illuminance) {
  char text[kMaxNumberText];
  const char* end = writeNumber(text, illuminance, illuminanceDigits_);
  addResLine(text, static_cast<std::size_t>(end - text));
}

void GridRows::addResLine(const char* text, std::size_t size) {
  // A fixed-size copy (a few moves, no call) into room for the longest text, then cut.
  const std::size_t start = res_.size();
  res_.resize(start + kMaxNumberText);
  std::memcpy(res_.data() + start, text, kMaxNumberText);
  res_[start + size] = '\n';
  res_.resize(start + size + 1);
}

}  // namespace penumbra
