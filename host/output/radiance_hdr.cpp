#include "output/radiance_hdr.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace penumbra {
namespace {

// A header line ends at the first newline: a value with one would end the header early.
std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}

// Ward's real pixel: the largest channel's exponent shared by all three, 8 bits of mantissa each
// (truncated; readers add half a step back). Below 1e-32 the pixel is black.
void appendRgbe(std::string& out, double r, double g, double b) {
  const double largest = std::max({r, g, b});
  if (!(largest > 1e-32)) {
    out.append(4, '\0');
    return;
  }
  int exponent = 0;
  const double scale = std::frexp(largest, &exponent) * 256.0 / largest;
  for (double c : {r, g, b}) {
    out += static_cast<char>(static_cast<unsigned char>(std::max(c, 0.0) * scale));
  }
  out += static_cast<char>(static_cast<unsigned char>(exponent + 128));
}

}  // namespace

std::string radianceViewOptions(const View& view) {
  const Vec3 direction = (view.target - view.eye).normalized();
  const double halfWidth = std::tan(view.fovDegrees * std::numbers::pi / 360.0);
  const double vertical =
      2.0 * std::atan(halfWidth * view.height / view.width) * 180.0 / std::numbers::pi;
  return fmt::format("-vtv -vp {} {} {} -vd {} {} {} -vu {} {} {} -vh {} -vv {}", view.eye.x(),
                     view.eye.y(), view.eye.z(), direction.x(), direction.y(), direction.z(),
                     view.up.x(), view.up.y(), view.up.z(), view.fovDegrees, vertical);
}

std::string encodeRadianceHdr(const RgbImage& luminance, const RadianceHeader& header) {
  std::string out = "#?RADIANCE\n";
  if (!header.software.empty()) out += "SOFTWARE=" + oneLine(header.software) + "\n";
  for (const auto& [name, value] : header.metadata) {
    out += oneLine(name) + "=" + oneLine(value) + "\n";
  }
  if (header.view) out += "VIEW= " + radianceViewOptions(*header.view) + "\n";
  // Rec. 709 primaries and D65 white: the RGB of the renders.
  out += "PRIMARIES= 0.640 0.330 0.300 0.600 0.150 0.060 0.3127 0.3290\n";
  out += "EXPOSURE=1\n";
  out += "FORMAT=32-bit_rle_rgbe\n\n";
  out += fmt::format("-Y {} +X {}\n", luminance.height, luminance.width);
  out.reserve(out.size() + luminance.rgb.size() / 3 * 4);
  for (std::size_t i = 0; i < luminance.rgb.size(); i += 3) {
    appendRgbe(out, luminance.rgb[i] / kRadianceLuminousEfficacy,
               luminance.rgb[i + 1] / kRadianceLuminousEfficacy,
               luminance.rgb[i + 2] / kRadianceLuminousEfficacy);
  }
  return out;
}

}  // namespace penumbra
