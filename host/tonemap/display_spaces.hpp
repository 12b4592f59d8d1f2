#pragma once
// Fang's colour spaces (thesis ch. 4.3, Fig. 4.4). Space 0 is the render's linear RGB (cd/m²);
// Space 1 maps all RGB linearly to [0, 1] (eq. 4.9-4.11); Space 2 is its HSV; Space 3 maps V to
// [LowerBound, 1] (eq. 4.12); the solved V goes back to RGB with H and S kept; Space 4 is device
// values ×255, rounded (eq. 4.13-4.15). Only V changes between Space 2 and the device.
#include <vector>

#include "image/images.hpp"
#include "tonemap/display_model.hpp"

namespace penumbra {

struct DisplaySpaces {
  int width = 0, height = 0;
  double lowerBound = 0;
  double minRgb = 0, maxRgb = 0;  // MinRGB, MaxRGB of eq. 4.9 over every channel of every pixel
  std::vector<float> value0;      // Space 0: V = max(R, G, B), cd/m²
  std::vector<float> value1;      // Space 1/2: V in [0, 1]
  std::vector<float> value3;      // Space 3: LowerBound + (1 - LowerBound) V1

  size_t index(int x, int y) const { return static_cast<size_t>(y) * width + x; }
};

// A display V as stored (float) that lies in [lowerBound, 1] also when compared in double: float
// rounding of 0.02 lands below 0.02, and the bounds are required (eq. 4.17).
float boundedDisplayValue(double value, double lowerBound);

// Non-finite or negative channels count as 0: a render never has them, a hand-made EXR might.
// With `faces`, MaxRGB is taken over the pixels that show a surface or a source (when some do):
// what a ray that leaves the scene shows (the sky through a window, the sun's disk at ~6e8 cd/m²)
// does not set the range of the room's own luminances; a background pixel above it shows V1 = 1,
// white. Without daylight the background is black and MaxRGB is the same either way.
DisplaySpaces displaySpaces(const RgbImage& hdr, double lowerBound,
                            const FaceIdImage* faces = nullptr);

// HSV → RGB with the pixel's Space-2 hue and saturation and the display V given per pixel, then
// Space 4. HSV → RGB is homogeneous in V, so this is the Space-1 colour scaled by V_display / V1.
DisplayImage deviceImage(const RgbImage& hdr, const DisplaySpaces& spaces,
                         const ScalarImage& displayValue);

// What the PNG holds: the same HSV → RGB, each channel read as a display luminance target (its
// share of the display's brightest, display_model.hpp) and encoded as the sRGB code value that
// shows it there, ×255 rounded. spaces.lowerBound must be display.lowerBound(), so that the
// darkest V is code 0 and V = 1 is code 255.
DisplayImage encodedImage(const RgbImage& hdr, const DisplaySpaces& spaces,
                          const ScalarImage& displayValue, const DisplayModel& display);

}  // namespace penumbra
