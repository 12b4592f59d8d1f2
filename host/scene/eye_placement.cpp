#include "scene/eye_placement.hpp"

#include <fmt/format.h>

namespace penumbra::scenefile {

void requireEyeOutsideSolids(const Vec3& eye, const std::string& owner, const Where& where,
                             const std::vector<Solid>& solids, const BuildContext& context) {
  for (const Solid& solid : solids) {
    if (solid.shape.containsStrictly(eye, context.tolerance)) {
      context.fail(where,
                   fmt::format("{}: the eye {} m is inside the solid '{}'; move it into the room",
                               owner, formatVec3(eye), solid.name));
    }
  }
}

}  // namespace penumbra::scenefile
