#pragma once
// How much of the contrast across visible edges a display image keeps: over every pair of
// 4-adjacent pixels on two different surfaces, the share whose display ratio lies within a
// tolerance of the Space-0 ratio. The thesis's claim is about exactly these pairs.
#include <cstddef>

#include "image/images.hpp"
#include "tonemap/display_model.hpp"

namespace penumbra {

struct EdgeContrastShare {
  size_t edges = 0;        // pixel pairs across an edge with light on both sides
  size_t displayable = 0;  // of those, the ones whose Space-0 ratio the display can show
  size_t kept = 0;         // ratio kept within the tolerance
  double share() const { return edges ? double(kept) / edges : 1.0; }
};

// displayValue: the display's V per pixel (ScalarImage in [black, 1]). tolerance: relative, e.g.
// 0.05 keeps a ratio r when it shows between r/1.05 and r·1.05.
EdgeContrastShare measureEdgeContrast(const RgbImage& hdr, const FaceIdImage& faces,
                                      const ScalarImage& displayValue, double black,
                                      double tolerance);

// The display V of an 8-bit image as toneMap() writes it: the luminance `display` shows for the
// largest channel's code value, as a share of its brightest (display_model.hpp).
ScalarImage displayValueOf(const DisplayImage& image, const DisplayModel& display);

}  // namespace penumbra
