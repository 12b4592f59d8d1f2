#pragma once
// `observers:` entries: the eyes `penumbra glare` rates (docs/scene-format.md, "Observers").
#include "scene/scene_spec.hpp"

namespace penumbra::scenefile {

// Reads one observer and checks what can be checked without the geometry: `eye` or `grid` (not
// both), a non-zero `look` with a horizontal component, a grid of non-zero area and spacing.
ObserverSpec readObserver(const Reader& reader, const Field& field);

}  // namespace penumbra::scenefile
