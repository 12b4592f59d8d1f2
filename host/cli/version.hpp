#pragma once

namespace penumbra {

// Keep in step with project(penumbra VERSION ...) in CMakeLists.txt; the build must not need git
// metadata (STACK.md pitfall 9), so the version is written down here.
inline constexpr const char* kVersion = "0.1.0";

}  // namespace penumbra
