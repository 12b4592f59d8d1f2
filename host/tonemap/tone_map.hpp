#pragma once
// The display step (Fang's thesis on constraint-based rendering for HDR scenes, ch. 4-5): an HDR
// render and its face-id AOV in, 8-bit display values out. No files here: the render command calls
// this in-process and the output layer writes the PNG and the statistics.
#include "image/images.hpp"
#include "tonemap/tone_map_options.hpp"

namespace penumbra {

// Display V per pixel (the thesis's V after the solve, before HSV → RGB and rounding): the
// display luminance target as a share of the target display's brightest, in
// [options.targetDisplay().lowerBound(), 1] (options.black without ambient light). Tests and the
// edge-contrast measure read this; toneMap() encodes it.
ScalarImage displayValues(const RgbImage& hdr, const FaceIdImage& faces,
                          const ToneMapOptions& options, ToneMapStats* stats = nullptr);

// The whole display step: display values, then hue and saturation back, each channel encoded as
// the sRGB code value that shows it on the target display (display_model.hpp), ×255 rounded.
DisplayImage toneMap(const RgbImage& hdr, const FaceIdImage& faces, const ToneMapOptions& options,
                     ToneMapStats* stats = nullptr);

}  // namespace penumbra
