#pragma once
// The scene's photometric luminaires as the kernels read them.
//
// The point model (kernels/luminaire.cl): one candela table per luminaire (scaled by its flux
// override and maintenance factor), one PnLuminaire per point source: a placed instance of the
// point model, or one cell of a subdivided opening (scene/luminaire.hpp) carrying its share of
// the table; and every solid's planes for the shadow test. Built in double, stored as float,
// positions relative to the same origin as the illuminance kernel's (kernel_scene.hpp).
//
// The area model (kernels/luminance_moments.cl): each placed instance whose opening's fit holds is
// a polygon source of polynomial luminance, evaluated by the illuminance kernel like a Lambertian
// source (unoccluded, penumbra paths, culling), in a scene of its own: the scene's solids and
// those sources.
#include <vector>

#include "cl/buffer.hpp"
#include "kernels/shared_types.h"
#include "scene/scene.hpp"

namespace penumbra {

struct LuminaireKernelScene {
  std::vector<PnLuminaire> luminaires;
  std::vector<int> instanceOf;  // per PnLuminaire, the placed instance it belongs to
  std::vector<PnCandelaTable> tables;
  std::vector<float> angles;   // degrees
  std::vector<float> candela;  // cd
  std::vector<PnShadowSolid> solids;
  std::vector<cl_float4> planes;
};

// Placed instances in the order the outputs list them: every instance of every luminaire, in
// scene order (IlluminanceResult::luminaireCount).
int placedInstanceCount(const Scene& scene);

// The point sources of `scene`'s luminaires; `origin` is subtracted from every position
// (KernelScene::origin).
LuminaireKernelScene packLuminaires(const Scene& scene, const Vec3& origin);

// The area model's openings as sources of polynomial luminance.
struct OpeningScene {
  Scene scene;                  // the solids, grids and the openings as sources (no luminaires)
  std::vector<int> instanceOf;  // per source, the placed instance it is
};

OpeningScene openingScene(const Scene& scene);

}  // namespace penumbra
