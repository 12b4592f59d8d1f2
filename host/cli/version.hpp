#pragma once

namespace penumbra {

// Keep in step with project(penumbra VERSION ...) in CMakeLists.txt; the build must work from a
// copy without .git (docs/building.md), so the version is written down here.
inline constexpr const char* kVersion = "0.1.0";

}  // namespace penumbra
