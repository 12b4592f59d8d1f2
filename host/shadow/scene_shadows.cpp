#include "shadow/scene_shadows.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>

namespace penumbra {

SceneShadows buildSceneShadows(const Scene& scene) {
  return buildSceneShadows(scene, [](EmittingFaceShadows&) {});
}

SceneShadows buildSceneShadows(const Scene& scene,
                               const std::function<void(EmittingFaceShadows&)>& consume) {
  SceneShadows shadows;
  shadows.tolerance = Tolerance::forSceneSize(scene.size());
  for (std::size_t s = 0; s < scene.sources.size(); ++s)
    for (const ConvexPolygon& face : scene.sources[s].faces)
      shadows.faces.push_back(EmittingFaceShadows{
          static_cast<int>(s), face, {}, findAperture(scene, face, shadows.tolerance)});

  // Every (face, solid) pair is independent: build them in parallel, a block of faces at a time
  // (so that a consumer that drops the casters holds one block's), then keep the non-empty ones
  // in order, so the result does not depend on the thread count.
  const std::size_t solids = scene.solids.size();
  constexpr std::size_t kFacesPerBlock = 64;
  std::vector<ShadowCaster> all;
  for (std::size_t first = 0; first < shadows.faces.size(); first += kFacesPerBlock) {
    const std::size_t count = std::min(kFacesPerBlock, shadows.faces.size() - first);
    all.assign(count * solids, ShadowCaster{});
    tbb::parallel_for(std::size_t{0}, all.size(), [&](std::size_t k) {
      const EmittingFaceShadows& f = shadows.faces[first + k / solids];
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
      if (!all[k].shape.empty())
        shadows.faces[first + k / solids].casters.push_back(std::move(all[k]));
    for (std::size_t f = first; f < first + count; ++f) consume(shadows.faces[f]);
  }
  return shadows;
}

}  // namespace penumbra
