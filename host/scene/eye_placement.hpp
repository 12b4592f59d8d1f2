#pragma once
// An eye (a camera's, an observer's) must lie outside every solid: inside a wall or a desk it
// would see the inside of a solid (black, or nothing) and every result from it would be wrong.
#include <string>
#include <vector>

#include "scene/build_context.hpp"
#include "scene/scene.hpp"

namespace penumbra::scenefile {

// Fails at `where` when `eye` lies strictly inside one of `solids`; `owner` names what the eye
// belongs to in the message ("view 'door'", "observer 'desk-1'").
void requireEyeOutsideSolids(const Vec3& eye, const std::string& owner, const Where& where,
                             const std::vector<Solid>& solids, const BuildContext& context);

}  // namespace penumbra::scenefile
