#pragma once
// Rectangle grids placed where they can only give zeros: outside every room volume, or facing
// away from every source (a warning each). docs/scene-format.md ("Warnings") states the criteria.
#include <optional>

#include "scene/scene.hpp"
#include "scene/yaml_reader.hpp"

namespace penumbra::scenefile {

// The warning for a `rect` grid of `scene` that lies outside the room or faces away from every
// source; nothing for other grids, for a grid wholly inside a solid (its points are reported as
// inside solids) and for a grid that is placed well.
std::optional<SceneWarning> misplacedGridWarning(const CalculationGrid& grid, const Where& where,
                                                 const Scene& scene, double tolerance);

}  // namespace penumbra::scenefile
