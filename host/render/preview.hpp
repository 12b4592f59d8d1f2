#pragma once
// A quick display copy of a render: luminance scaled linearly so that the 99th percentile of the
// surfaces' luminance is white, clipped above (sources and sunlit patches), and encoded with the
// sRGB curve for a screen. This is not the tone map (host/tonemap does that properly); it is what
// `penumbra render --display preview` writes.
#include "image/images.hpp"

namespace penumbra {

DisplayImage linearPreview(const RgbImage& luminance, const FaceIdImage& faces);

}  // namespace penumbra
