#pragma once
// What the second pass of loading (SceneSpec → Scene) needs besides the spec: the file for
// messages and the input tolerances.
#include <filesystem>
#include <functional>
#include <string>

#include "geometry/tolerance.hpp"
#include "scene/yaml_reader.hpp"

namespace penumbra::scenefile {

// Tolerance::kInputAngle (the tolerance policy lives in one place).
inline constexpr double kInputAngleTolerance = Tolerance::kInputAngle;

struct BuildContext {
  std::filesystem::path file;
  double tolerance = 1e-6;  // m: Tolerance::kRelativeInput × the scene's size
  // Unit direction from a point towards the scene's strongest source there: curved primitives
  // orient their facets by it. Unset (while the sources themselves are built): +z.
  std::function<Vec3(const Vec3&)> towardsLight;

  [[noreturn]] void fail(const Where& where, const std::string& message) const {
    scenefile::fail(file, where, message);
  }
};

}  // namespace penumbra::scenefile
