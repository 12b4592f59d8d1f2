#pragma once
// A scene's warnings on the terminal, before the long part of a command, as compilers print
// theirs ("office.yaml:31: warning: sources[1]: ...").
#include <cstdio>

#include <fmt/format.h>

#include "scene/scene.hpp"

namespace penumbra {

inline void printSceneWarnings(const Scene& scene) {
  for (const SceneWarning& warning : scene.warnings) {
    fmt::print(stderr, "{}\n", warningText(scene.file, warning));
  }
}

}  // namespace penumbra
