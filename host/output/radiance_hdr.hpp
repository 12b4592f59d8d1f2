#pragma once
// Radiance's RGBE picture format (Ward, "Real Pixels", Graphics Gems II; the header as Radiance's
// getheader reads it), written by penumbra itself: OpenImageIO's writer emits neither a VIEW= line
// nor free header lines, and without VIEW= Radiance's tools (findglare, evalglare, pcomb's view
// queries) cannot know the picture's camera.
//
// Radiance pictures hold radiance in W/(sr·m²) with its luminous efficacy of 179 lm/W for white:
// a channel holds L / 179 for a luminance L in cd/m², so that pvalue, falsecolor and evalglare,
// which multiply by 179, give cd/m² back.
#include <optional>
#include <string>

#include "image/images.hpp"
#include "scene/scene.hpp"

namespace penumbra {

inline constexpr double kRadianceLuminousEfficacy = 179.0;  // lm/W, Radiance's WHTEFFICACY

struct RadianceHeader {
  std::optional<View> view;  // written as VIEW= (Radiance's perspective view)
  std::string software;      // SOFTWARE=
  ImageMetadata metadata;    // one "name=value" line each (penumbra:view=from-door, ...)
};

// "-vtv -vp x y z -vd dx dy dz -vu ux uy uz -vh H -vv V": the pinhole camera of `view` as
// Radiance's view options. H is the horizontal full angle, V the vertical one that square pixels
// give (tan(V/2) = tan(H/2)·height/width), both in degrees from image edge to image edge.
std::string radianceViewOptions(const View& view);

// The whole file: header, resolution line "-Y height +X width" (top row first, left to right),
// then flat RGBE pixels (every scanline as plain 4-byte pixels, which every RGBE reader accepts).
// `luminance` is in cd/m² per channel; it is stored as radiance, L / 179.
std::string encodeRadianceHdr(const RgbImage& luminance, const RadianceHeader& header);

}  // namespace penumbra
