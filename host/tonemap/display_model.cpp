#include "tonemap/display_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace penumbra {

double srgbDecode(double code) {
  return code <= 0.04045 ? code / 12.92 : std::pow((code + 0.055) / 1.055, 2.4);
}

double srgbEncode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double DisplayModel::reflectedLuminance() const {
  return kReflectivity * ambient / std::numbers::pi;
}

double DisplayModel::darkest() const {
  return blackLuminance() + reflectedLuminance();
}

double DisplayModel::brightest() const {
  return peakLuminance + reflectedLuminance();
}

double DisplayModel::lowerBound() const {
  // In shares of the panel's white, so that with no ambient light the bound is the black share
  // as given, to the last bit (the tone map's bounds are exact).
  const double reflected = reflectedLuminance() / peakLuminance;
  return (blackShare + reflected) / (1.0 + reflected);
}

double DisplayModel::luminance(double code) const {
  return (peakLuminance - blackLuminance()) * srgbDecode(code) + darkest();
}

double DisplayModel::codeValue(double luminance) const {
  const double relative = (luminance - darkest()) / (peakLuminance - blackLuminance());
  // White is code 1 exactly (sRGB's formula gives 1 − 1e-16 there).
  return relative >= 1.0 ? 1.0 : srgbEncode(std::max(relative, 0.0));
}

}  // namespace penumbra
