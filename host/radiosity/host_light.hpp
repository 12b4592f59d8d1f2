#pragma once
// Direct light that the engine does not hold, computed on the host and handed to the
// interreflection as functions, so that radiosity/ needs nothing of illuminance/: E (lx) at each
// point, white.
#include <functional>
#include <span>
#include <vector>

#include "geometry/sample_point.hpp"

namespace penumbra {

using HostDirectLight = std::function<std::vector<double>(std::span<const SamplePoint>)>;

struct HostLight {
  // The sky and ground past obstructions outside the room (illuminance/skylight.hpp): a light
  // group of its own, solved with the rest.
  HostDirectLight sky;
  // The sun's direct light (illuminance/sunlight.hpp): a right-hand side solved apart, so that
  // its part of the interreflected light is known.
  HostDirectLight sun;
};

}  // namespace penumbra
