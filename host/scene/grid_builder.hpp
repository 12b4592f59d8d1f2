#pragma once
// Lays out calculation points: work planes (EN 12464-1 grids over the room's floor), rectangles
// and point lists.
#include <optional>

#include "scene/build_context.hpp"
#include "scene/scene.hpp"
#include "scene/scene_spec.hpp"

namespace penumbra::scenefile {

// EN 12464-1 maximum grid spacing (m) for a calculation area whose longer side is d (m):
// p = 0.2 · 5^log10(d), and never more than 10 m.
double en12464Spacing(double d);

// The number of cells along a side of length `side` for a maximum spacing p: ceil(side / p).
int cellCount(double side, double p);

// `room` is needed by work planes; it is empty when the scene has no room.
CalculationGrid buildGrid(const GridSpec& spec, const std::optional<Room>& room,
                          const BuildContext& context);

}  // namespace penumbra::scenefile
