#include "shadow/scene_shadows.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <future>
#include <stdexcept>

namespace penumbra {

SceneShadows buildSceneShadows(const Scene& scene) {
  return buildSceneShadows(scene, [](EmittingFaceShadows&) {});
}

SceneShadows buildSceneShadows(const Scene& scene,
                               const std::function<void(EmittingFaceShadows&)>& consume) {
  SceneShadows shadows;
  shadows.tolerance = Tolerance::forSceneSize(scene.size());
  std::vector<int> firstFace(scene.sources.size(), -1);
  for (std::size_t s = 0; s < scene.sources.size(); ++s) {
    firstFace[s] = static_cast<int>(shadows.faces.size());
    for (const ConvexPolygon& face : scene.sources[s].faces)
      shadows.faces.push_back(EmittingFaceShadows{static_cast<int>(s),
                                                  face,
                                                  {},
                                                  findAperture(scene, face, shadows.tolerance),
                                                  -1,
                                                  !scene.sources[s].castersOnly});
  }
  for (std::size_t s = 0; s < scene.sources.size(); ++s) {
    const int owner = scene.sources[s].castersOf;
    if (owner < 0) continue;
    if (scene.sources[s].faces.size() != 1 || owner >= static_cast<int>(s) ||
        scene.sources[owner].castersOf >= 0)
      throw std::logic_error(
          "buildSceneShadows: a source shares the casters of an earlier "
          "source that has its own, and has one face");
    shadows.faces[firstFace[s]].casterOwner = firstFace[owner];
  }

  // Every (face, solid) pair is independent: build them in parallel, a block of faces at a time
  // (so that a consumer that drops the casters holds two blocks'), then keep the non-empty ones
  // in order, so the result does not depend on the thread count. The next block is built on a
  // second thread while this one is kept and consumed (packing its casters for the kernel takes
  // as long as building them, one face after another).
  const std::size_t solids = scene.solids.size();
  constexpr std::size_t kFacesPerBlock = 64;
  const auto buildBlock = [&](std::size_t first, std::vector<ShadowCaster>& all) {
    const std::size_t count = std::min(kFacesPerBlock, shadows.faces.size() - first);
    all.assign(count * solids, ShadowCaster{});
    tbb::parallel_for(std::size_t{0}, all.size(), [&](std::size_t k) {
      const EmittingFaceShadows& f = shadows.faces[first + k / solids];
      if (f.casterOwner >= 0) return;
      ShadowCaster& caster = all[k];
      caster.solid = static_cast<int>(k % solids);
      caster.shape = scene.solids[caster.solid].shape.clipped(f.face.plane().flipped(),
                                                              shadows.tolerance.length);
      if (caster.shape.empty()) return;
      caster.volume = shadowVolume(f.face, caster.shape, shadows.tolerance);
      if (f.aperture)
        caster.behindAperture = behindAperture(*f.aperture, caster.shape, shadows.tolerance);
    });
  };
  std::vector<ShadowCaster> built, building;
  // Declared after the buffers: an exception waits for the block being built before they go.
  std::future<void> next;
  if (!shadows.faces.empty()) buildBlock(0, built);
  for (std::size_t first = 0; first < shadows.faces.size(); first += kFacesPerBlock) {
    const std::size_t following = first + kFacesPerBlock;
    if (following < shadows.faces.size())
      next = std::async(std::launch::async, buildBlock, following, std::ref(building));
    const std::size_t count = std::min(kFacesPerBlock, shadows.faces.size() - first);
    for (std::size_t k = 0; k < built.size(); ++k)
      if (!built[k].shape.empty())
        shadows.faces[first + k / solids].casters.push_back(std::move(built[k]));
    for (std::size_t f = first; f < first + count; ++f) consume(shadows.faces[f]);
    if (next.valid()) next.get();
    std::swap(built, building);
  }
  return shadows;
}

}  // namespace penumbra
