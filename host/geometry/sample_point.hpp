#pragma once
#include "geometry/vec.hpp"

namespace penumbra {

// A point where illuminance is wanted: position (m), unit normal of the receiving surface, and
// the solid whose surface it lies on (that solid never shades it), -1 when it lies on none.
struct SamplePoint {
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  int solid = -1;
};

}  // namespace penumbra
