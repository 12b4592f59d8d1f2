#pragma once
// A Radiance picture read by Radiance's rules, written for the tests from the format's description
// (Ward, "Real Pixels", Graphics Gems II; Radiance's header.c and color.c), independent of the
// writer: the header is text lines up to the first empty line, the first "#?RADIANCE"; then the
// resolution line "-Y height +X width"; then scanlines, each either flat 4-byte pixels or
// run-length encoded per component (starting 2, 2, width >> 8, width & 255). A pixel (r, g, b, e)
// is ((r + 0.5)·2^(e − 136), ...), or black for e = 0.
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace penumbra::testing {

struct RadiancePicture {
  std::vector<std::string> header;  // every header line, in order, without the newline
  int width = 0, height = 0;
  std::vector<float> rgb;  // row-major, top row first, in the file's units (W/(sr·m²))

  // The value of "NAME=..." (text after '='), "" when there is no such line.
  std::string value(const std::string& name) const {
    for (const std::string& line : header) {
      if (line.rfind(name + "=", 0) == 0) return line.substr(name.size() + 1);
    }
    return "";
  }
};

inline RadiancePicture readRadiancePicture(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + file.string());
  RadiancePicture picture;
  std::string line;
  while (std::getline(in, line) && !line.empty()) picture.header.push_back(line);
  if (picture.header.empty() || picture.header.front() != "#?RADIANCE") {
    throw std::runtime_error(file.string() + ": no #?RADIANCE magic line");
  }
  std::getline(in, line);
  std::istringstream resolution(line);
  std::string y, x;
  resolution >> y >> picture.height >> x >> picture.width;
  if (y != "-Y" || x != "+X") throw std::runtime_error("unexpected resolution line " + line);

  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
  std::size_t at = 0;
  const auto next = [&]() -> std::uint8_t {
    if (at >= bytes.size()) throw std::runtime_error(file.string() + ": pixels end early");
    return bytes[at++];
  };
  const int w = picture.width;
  std::vector<std::uint8_t> scanline(static_cast<std::size_t>(w) * 4);
  for (int row = 0; row < picture.height; ++row) {
    const bool encoded = w >= 8 && w < 32768 && at + 4 <= bytes.size() && bytes[at] == 2 &&
                         bytes[at + 1] == 2 && (bytes[at + 2] & 0x80) == 0;
    if (encoded) {
      if (((bytes[at + 2] << 8) | bytes[at + 3]) != w) throw std::runtime_error("scanline length");
      at += 4;
      for (int component = 0; component < 4; ++component) {
        for (int x0 = 0; x0 < w;) {
          int count = next();
          if (count > 128) {  // a run
            count -= 128;
            const std::uint8_t v = next();
            for (int k = 0; k < count; ++k) scanline[(x0++) * 4 + component] = v;
          } else {
            for (int k = 0; k < count; ++k) scanline[(x0++) * 4 + component] = next();
          }
        }
      }
    } else {
      for (auto& b : scanline) b = next();
    }
    for (int x0 = 0; x0 < w; ++x0) {
      const std::uint8_t* p = &scanline[static_cast<std::size_t>(x0) * 4];
      for (int c = 0; c < 3; ++c) {
        picture.rgb.push_back(p[3] == 0 ? 0.0f
                                        : static_cast<float>(std::ldexp(p[c] + 0.5, p[3] - 136)));
      }
    }
  }
  return picture;
}

}  // namespace penumbra::testing
