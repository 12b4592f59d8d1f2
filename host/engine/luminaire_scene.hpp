#pragma once
// The scene's photometric luminaires and solids as kernels/luminaire.cl reads them: one candela
// table per luminaire (scaled by its flux override and maintenance factor), one PnLuminaire per
// placed instance, and every solid's planes for the shadow test. Built in double, stored as
// float, positions relative to the same origin as the illuminance kernel's (kernel_scene.hpp).
#include <vector>

#include "cl/buffer.hpp"
#include "kernels/shared_types.h"
#include "scene/scene.hpp"

namespace penumbra {

struct LuminaireKernelScene {
  std::vector<PnLuminaire> luminaires;
  std::vector<PnCandelaTable> tables;
  std::vector<float> angles;   // degrees
  std::vector<float> candela;  // cd
  std::vector<PnShadowSolid> solids;
  std::vector<cl_float4> planes;
};

// `origin` is subtracted from every position (KernelScene::origin).
LuminaireKernelScene packLuminaires(const Scene& scene, const Vec3& origin);

}  // namespace penumbra
