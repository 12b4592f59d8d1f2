#include "shadow/scene_shadows.hpp"

#include <tbb/parallel_for.h>

namespace penumbra {

SceneShadows buildSceneShadows(const Scene& scene) {
  SceneShadows shadows;
  shadows.tolerance = Tolerance::forSceneSize(scene.size());
  for (std::size_t s = 0; s < scene.sources.size(); ++s)
    for (const ConvexPolygon& face : scene.sources[s].faces)
      shadows.faces.push_back(EmittingFaceShadows{
          static_cast<int>(s), face, {}, findAperture(scene, face, shadows.tolerance)});

  // Every (face, solid) pair is independent: build them in parallel, then drop the empty ones
  // in order, so the result does not depend on the thread count.
  const std::size_t solids = scene.solids.size();
  std::vector<ShadowCaster> all(shadows.faces.size() * solids);
  tbb::parallel_for(std::size_t{0}, all.size(), [&](std::size_t k) {
    const EmittingFaceShadows& f = shadows.faces[k / solids];
    ShadowCaster& caster = all[k];
    caster.solid = static_cast<int>(k % solids);
    caster.shape = scene.solids[caster.solid].shape.clipped(f.face.plane().flipped(),
                                                            shadows.tolerance.length);
    if (caster.shape.empty()) return;
    caster.volume = shadowVolume(f.face, caster.shape, shadows.tolerance);
    if (f.aperture)
      caster.behindAperture = behindAperture(*f.aperture, caster.shape, shadows.tolerance);
  });
  for (std::size_t k = 0; k < all.size(); ++k)
    if (!all[k].shape.empty()) shadows.faces[k / solids].casters.push_back(std::move(all[k]));
  return shadows;
}

}  // namespace penumbra
