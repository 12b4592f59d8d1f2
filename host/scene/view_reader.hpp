#pragma once
// `views:` entries: cameras for `penumbra render` (docs/scene-format.md, "Views").
#include "scene/scene_spec.hpp"

namespace penumbra::scenefile {

// Reads one view and checks what can be checked without the geometry: a line of sight of
// non-zero length, `up` not along it, a field of view in (0°, 170°], a size in whole pixels.
ViewSpec readView(const Reader& reader, const Field& field);

// The largest image side penumbra renders (pixels): beyond it the buffers of one render would
// exceed what a workstation's device holds.
inline constexpr int kMaxViewSide = 16384;

}  // namespace penumbra::scenefile
