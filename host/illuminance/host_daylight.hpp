#pragma once
// The direct light of a daylight scene that the interreflection takes from the host
// (radiosity/host_light.hpp), for every caller that solves it (the grids' Estimator, the
// renderer): the sky and ground past obstructions where the kernel's sources cannot hold them
// (scene/daylight.hpp, skyOnHost; surfaceSkylight), and the sun (sunlight). Empty functions where
// the scene has neither. The functions refer to `scene`, which must outlive them.
#include "radiosity/host_light.hpp"
#include "scene/scene.hpp"

namespace penumbra {

HostLight hostDaylight(const Scene& scene);

}  // namespace penumbra
