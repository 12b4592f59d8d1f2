#pragma once
// IlluminanceEngine::evaluate for a scene with a sky (scene/daylight.hpp): the points are
// evaluated in groups that share the sky and ground faces' cut, the engine taking each group's
// daylightScene in turn, and the results put back in the points' order. Without a sky it is
// engine.evaluate. The engine holds the last group's scene afterwards: callers that use a sky
// evaluate through this function only.
#include <span>

#include "engine/illuminance_engine.hpp"
#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// E at `points` from `scene`'s sources, its sky and ground (daylightScene's sources, in its
// order: the scene's own, then a sky and a ground source per sky-lit opening) and luminaires.
IlluminanceResult evaluateDaylight(IlluminanceEngine& engine, const Scene& scene,
                                   std::span<const SamplePoint> points, bool bySource = false);

}  // namespace penumbra
