#pragma once
// The SceneError a scene text throws, for the tests of the scene reader's messages.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "scene/scene_loader.hpp"

namespace penumbra::testing {

// The SceneError that parsing `yaml` (as the file `file`) throws; fails the test when it parses.
inline SceneError sceneErrorOf(const std::string& yaml, const std::filesystem::path& file) {
  try {
    parseScene(yaml, file);
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a SceneError for:\n" << yaml;
  return SceneError(file, -1, "", "none");
}

}  // namespace penumbra::testing
