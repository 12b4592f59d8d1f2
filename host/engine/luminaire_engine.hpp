#pragma once
// Photometric luminaires on the device: E at sample points from every placed luminaire of a
// scene. The point model (and the cells of a subdivided opening) by kernels/luminaire.cl, with
// hard shadows from the scene's solids; the area model's openings by the illuminance kernel, as
// sources of polynomial luminance (kernels/luminance_moments.cl) with exact penumbrae, in a scene
// of their own (engine/luminaire_scene.hpp). IlluminanceEngine adds the sum to the Lambertian
// sources' E.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "cl/device.hpp"
#include "engine/engine_options.hpp"
#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"
#include "shadow/shadow_class.hpp"

namespace penumbra {

class LuminaireEngine {
 public:
  // Builds the program (kernels/luminaire.cl); `options` are the illuminance kernel's paths for
  // the area model's openings.
  explicit LuminaireEngine(compute::Device& device, const EngineOptions& options = {});
  ~LuminaireEngine();

  // Uploads the luminaires and solids of `scene`, positions relative to `origin`, with the
  // kernel's absolute length tolerance `epsLength` (m), both as the illuminance kernel has them.
  void setScene(const Scene& scene, const Vec3& origin, float epsLength);

  struct Result {
    std::vector<double> illuminance;  // lx per point, every luminaire
    // [point * luminaires + l], per placed instance l: the point model Lit where the point sees
    // the centre in front of its surface, else Umbra; a subdivided opening Lit where it sees
    // every cell, Penumbra where some, Umbra where none; the area model the opening's shadow
    // class where light arrives, else Umbra.
    std::vector<ShadowClass> shadow;
    int luminaires = 0;  // placed luminaires (instances)
  };

  // E in lx at every point from every luminaire, and each one's shadow class.
  Result evaluate(std::span<const SamplePoint> points);

 private:
  // The point sources' part (kernels/luminaire.cl): E per point, and `seen` [point * sources +
  // source], 1 where the point sees the source in front of its surface.
  struct PointSources {
    std::vector<double> illuminance;
    std::vector<std::uint8_t> seen;
  };
  PointSources evaluatePointSources(std::span<const SamplePoint> points);

  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace penumbra
