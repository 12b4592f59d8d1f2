#pragma once
// How a subcommand ends on an error, the same for every command: an invalid scene or study (a
// SceneError, already "file:line: key: message", the form editors turn into a link) is exit
// status 2; any other error is "penumbra: error: ..." and status 1.
#include <fmt/format.h>

#include <cstdio>
#include <exception>

#include "scene/scene_loader.hpp"

namespace penumbra::cli {

// Runs `work` (returning the exit status) and turns what it throws into a message and a status.
template <typename Work>
int reportingErrors(Work work) {
  try {
    return work();
  } catch (const SceneError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "penumbra: error: {}\n", e.what());
    return 1;
  }
}

}  // namespace penumbra::cli
