#pragma once
// The display step (Fang's thesis on constraint-based rendering for HDR scenes, ch. 4-5): an HDR
// render and its face-id AOV in, 8-bit display values out. No files here: the render command calls
// this in-process and the output layer writes the PNG and the statistics.
#include "image/images.hpp"
#include "tonemap/tone_map_options.hpp"

namespace penumbra {

// Display V per pixel (the thesis's V after the solve, before HSV → RGB and rounding), in
// [options.black, 1]. Tests and the edge-contrast measure read this; toneMap() quantises it.
ScalarImage displayValues(const RgbImage& hdr, const FaceIdImage& faces,
                          const ToneMapOptions& options, ToneMapStats* stats = nullptr);

// The whole display step: display values, then hue and saturation back (Space 4, ×255 rounded).
DisplayImage toneMap(const RgbImage& hdr, const FaceIdImage& faces, const ToneMapOptions& options,
                     ToneMapStats* stats = nullptr);

}  // namespace penumbra
