#pragma once
// E in lx at sample points, as the run being drawn computed it: the total (direct +
// interreflected) where the run had interreflection, the direct light for a direct-only run.
// What the surfaces plot and the iso-band drawings evaluate, so that their values are the grids'.
#include <functional>
#include <span>
#include <vector>

#include "engine/illuminance_engine.hpp"
#include "geometry/sample_point.hpp"

namespace penumbra::viz {

using PointLight = std::function<std::vector<double>(std::span<const SamplePoint>)>;

// The direct light of `engine`'s scene (the engine must outlive the result).
inline PointLight directLight(IlluminanceEngine& engine) {
  return [&engine](std::span<const SamplePoint> points) { return engine.illuminance(points); };
}

}  // namespace penumbra::viz
