#include "illuminance/host_daylight.hpp"

#include "illuminance/skylight.hpp"
#include "illuminance/sunlight.hpp"
#include "scene/daylight.hpp"

namespace penumbra {

HostLight hostDaylight(const Scene& scene) {
  HostLight host;
  const Scene* lit = &scene;
  if (skyOnHost(scene))
    host.sky = [lit](std::span<const SamplePoint> points) { return surfaceSkylight(*lit, points); };
  if (scene.sun)
    host.sun = [lit](std::span<const SamplePoint> points) { return sunlight(*lit, points); };
  return host;
}

}  // namespace penumbra
