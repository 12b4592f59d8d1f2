#include "tonemap/display_spaces.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace penumbra {
namespace {

double channel(float value) {
  return std::isfinite(value) && value > 0 ? value : 0.0;
}

}  // namespace

float boundedDisplayValue(double value, double lowerBound) {
  float v = static_cast<float>(std::clamp(value, lowerBound, 1.0));
  if (v < lowerBound) v = std::nextafter(v, 1.0f);
  return v;
}

DisplaySpaces displaySpaces(const RgbImage& hdr, double lowerBound, const FaceIdImage* faces) {
  if (!(lowerBound > 0 && lowerBound < 1)) {
    throw std::invalid_argument("the display's black level must lie in (0, 1)");
  }
  DisplaySpaces spaces;
  spaces.width = hdr.width;
  spaces.height = hdr.height;
  spaces.lowerBound = lowerBound;
  const size_t count = static_cast<size_t>(hdr.width) * hdr.height;
  const bool someSurface =
      faces && std::any_of(faces->ids.begin(), faces->ids.end(),
                           [](uint32_t id) { return id != FaceIdImage::kNoSurface; });
  double minRgb = count ? INFINITY : 0, maxRgb = 0;
  for (size_t i = 0; i < hdr.rgb.size(); ++i) {
    const double value = channel(hdr.rgb[i]);
    minRgb = std::min(minRgb, value);
    if (!someSurface || faces->ids[i / 3] != FaceIdImage::kNoSurface)
      maxRgb = std::max(maxRgb, value);
  }
  spaces.minRgb = minRgb;
  spaces.maxRgb = maxRgb;
  const double range = maxRgb - minRgb;
  spaces.value0.resize(count);
  spaces.value1.resize(count);
  spaces.value3.resize(count);
  for (size_t i = 0; i < count; ++i) {
    const float* rgb = &hdr.rgb[i * 3];
    const double v0 = std::max({channel(rgb[0]), channel(rgb[1]), channel(rgb[2])});
    // An image of one value has no range to map: it is shown white, not divided by zero.
    const double v1 =
        range > 0 ? std::min(1.0, (v0 - minRgb) / range) : (v0 > maxRgb || maxRgb > 0 ? 1.0 : 0.0);
    spaces.value0[i] = static_cast<float>(v0);
    spaces.value1[i] = static_cast<float>(v1);
    spaces.value3[i] = static_cast<float>(lowerBound + (1 - lowerBound) * v1);
  }
  return spaces;
}

namespace {

// HSV → RGB with the display V per pixel (Fig. 4.3), each channel's value in [0, 1] through
// `toByte`. HSV → RGB is homogeneous in V: the Space-1 colour scaled by V / V1.
template <typename ToByte>
DisplayImage displayChannels(const RgbImage& hdr, const DisplaySpaces& spaces,
                             const ScalarImage& displayValue, ToByte toByte) {
  DisplayImage image;
  image.width = hdr.width;
  image.height = hdr.height;
  image.channels = 3;
  const size_t count = static_cast<size_t>(hdr.width) * hdr.height;
  image.values.resize(count * 3);
  const double range = spaces.maxRgb - spaces.minRgb;
  for (size_t i = 0; i < count; ++i) {
    const double v = displayValue.values[i];
    const double v1 = spaces.value1[i];
    for (int c = 0; c < 3; ++c) {
      // Space 1 of this channel; a grey (V1 = 0, S = 0) is V in every channel (Fig. 4.3).
      const double c1 = range > 0 ? (channel(hdr.rgb[i * 3 + c]) - spaces.minRgb) / range : v1;
      const double out = v1 > 0 ? c1 * (v / v1) : v;
      image.values[i * 3 + c] = toByte(std::clamp(out, 0.0, 1.0));
    }
  }
  return image;
}

uint8_t byteOf(double unit) {
  return static_cast<uint8_t>(std::lround(unit * 255.0));
}

}  // namespace

DisplayImage deviceImage(const RgbImage& hdr, const DisplaySpaces& spaces,
                         const ScalarImage& displayValue) {
  return displayChannels(hdr, spaces, displayValue, byteOf);
}

DisplayImage encodedImage(const RgbImage& hdr, const DisplaySpaces& spaces,
                          const ScalarImage& displayValue, const DisplayModel& display) {
  return displayChannels(hdr, spaces, displayValue, [&display](double share) {
    return byteOf(display.codeValueOfShare(share));
  });
}

}  // namespace penumbra
