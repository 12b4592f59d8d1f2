#pragma once
// The three ways a shaded point's E is computed, which a test runs alike: the eight-lane path
// (culling, the default), the scalar path (culling, one lane at a time) and the plain path (no
// culling: every occluder tested at every point, the scalar contour).

#include <array>

#include "engine/illuminance_engine.hpp"

namespace penumbra::testing {

struct PenumbraPath {
  const char* name;
  EngineOptions options;
};

inline std::array<PenumbraPath, 3> penumbraPaths() {
  EngineOptions scalar;
  scalar.vectorPenumbra = false;
  EngineOptions plain;
  plain.culling = false;
  return {{{"eight lanes", {}}, {"scalar", scalar}, {"plain", plain}}};
}

}  // namespace penumbra::testing
