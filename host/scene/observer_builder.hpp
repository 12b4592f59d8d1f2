#pragma once
// From `observers:` entries to the scene's Observers: grids expanded into one eye per cell
// centre, every eye checked against the solids, the default lines of sight filled in.
#include <vector>

#include "scene/build_context.hpp"
#include "scene/scene.hpp"
#include "scene/scene_spec.hpp"

namespace penumbra::scenefile {

// The four horizontal axis directions +x, +y, −x, −y: the lines of sight rated when an observer
// gives no `look` (a seated worker may face any wall).
std::vector<Vec3> defaultLooks();

std::vector<Observer> buildObservers(const ObserverSpec& spec, const std::vector<Solid>& solids,
                                     const BuildContext& context);

}  // namespace penumbra::scenefile
