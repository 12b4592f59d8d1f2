#pragma once
// Sources placed where their light cannot go anywhere: inside a solid (an error), or lighting no
// calculation point and no surface (a warning). docs/scene-format.md ("Warnings") states the
// criteria.
#include <optional>

#include "scene/build_context.hpp"
#include "scene/scene.hpp"

namespace penumbra::scenefile {

// A source wholly inside a solid (a ceiling panel modelled in the ceiling slab) is a SceneError at
// `where`, naming the solid.
void requireSourceOutsideSolids(const Source& source, const Where& where,
                                const std::vector<Solid>& solids, const BuildContext& context);

// The warning for a source whose light reaches no calculation point of `scene`'s grids and no
// surface of its solids (none in front of it, or it is outside the room with no opening to shine
// through); nothing when it reaches something.
std::optional<SceneWarning> unlitWarning(const Source& source, const Where& where,
                                         const Scene& scene, double tolerance);

}  // namespace penumbra::scenefile
