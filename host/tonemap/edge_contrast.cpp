#include "tonemap/edge_contrast.hpp"

#include <algorithm>
#include <cmath>

#include "tonemap/region_map.hpp"

namespace penumbra {
namespace {

double space0(const RgbImage& hdr, size_t i) {
  const float* c = &hdr.rgb[i * 3];
  return std::max({c[0], c[1], c[2]});
}

}  // namespace

EdgeContrastShare measureEdgeContrast(const RgbImage& hdr, const FaceIdImage& faces,
                                      const ScalarImage& displayValue, double black,
                                      double tolerance) {
  EdgeContrastShare result;
  const double limit = std::log1p(tolerance);
  const auto pair = [&](size_t a, size_t b) {
    if (faces.ids[a] == faces.ids[b] || faces.ids[a] == FaceIdImage::kNoSurface ||
        faces.ids[b] == FaceIdImage::kNoSurface) {
      return;
    }
    const double va = space0(hdr, a), vb = space0(hdr, b);
    if (!(va > 0 && vb > 0)) return;
    ++result.edges;
    const double wanted = std::log(va / vb);
    if (std::abs(wanted) <= -std::log(black)) ++result.displayable;
    const double shown = std::log(double(displayValue.values[a]) / displayValue.values[b]);
    if (std::abs(shown - wanted) <= limit) ++result.kept;
  };
  forEachAdjacentPair(faces.width, faces.height, pair);
  return result;
}

ScalarImage displayValueOf(const DisplayImage& image, const DisplayModel& display) {
  ScalarImage values(image.width, image.height);
  for (size_t i = 0; i < values.values.size(); ++i) {
    uint8_t largest = 0;
    for (int c = 0; c < image.channels; ++c) {
      largest = std::max(largest, image.values[i * image.channels + c]);
    }
    values.values[i] = static_cast<float>(display.luminance(largest / 255.0) / display.brightest());
  }
  return values;
}

}  // namespace penumbra
