#include "render/preview.hpp"

#include <algorithm>
#include <cmath>

namespace penumbra {
namespace {

double srgbEncode(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

}  // namespace

DisplayImage linearPreview(const RgbImage& luminance, const FaceIdImage& faces) {
  std::vector<float> y;
  const std::size_t n = static_cast<std::size_t>(luminance.width) * luminance.height;
  for (std::size_t i = 0; i < n; ++i) {
    if (faces.ids[i] == FaceIdImage::kNoSurface) continue;
    const float* p = &luminance.rgb[i * 3];
    y.push_back(0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2]);
  }
  double white = 1.0;
  if (!y.empty()) {
    const auto at = y.begin() + static_cast<std::ptrdiff_t>(0.99 * (y.size() - 1));
    std::nth_element(y.begin(), at, y.end());
    white = *at > 0.0f ? *at : 1.0;
  }
  DisplayImage image{luminance.width, luminance.height, 3, std::vector<uint8_t>(n * 3)};
  for (std::size_t i = 0; i < n * 3; ++i) {
    const double v = std::clamp(luminance.rgb[i] / white, 0.0, 1.0);
    image.values[i] = static_cast<uint8_t>(std::lround(255.0 * srgbEncode(v)));
  }
  return image;
}

}  // namespace penumbra
