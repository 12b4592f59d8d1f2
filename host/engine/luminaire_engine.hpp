#pragma once
// The point model of photometric luminaires on the device (kernels/luminaire.cl): E at sample
// points from every placed luminaire of a scene, with hard shadows from its solids.
// IlluminanceEngine adds it to the Lambertian sources' E.
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "cl/device.hpp"
#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

class LuminaireEngine {
 public:
  // Builds the program (kernels/luminaire.cl).
  explicit LuminaireEngine(compute::Device& device);
  ~LuminaireEngine();

  // Uploads the luminaires and solids of `scene`, positions relative to `origin`, with the
  // kernel's absolute length tolerance `epsLength` (m), both as the illuminance kernel has them.
  // Throws std::runtime_error for a luminaire of the area model, which only the host reference
  // evaluates (reference/opening_illuminance.hpp).
  void setScene(const Scene& scene, const Vec3& origin, float epsLength);

  struct Result {
    std::vector<double> illuminance;  // lx per point, every luminaire
    // [point * luminaires + l]: 1 when the point sees luminaire l's centre in front of its
    // surface, 0 when it is behind the surface or shaded.
    std::vector<std::uint8_t> seen;
    int luminaires = 0;  // placed luminaires (instances)
  };

  // E in lx at every point from every luminaire, and which luminaires each point sees.
  Result evaluate(std::span<const SamplePoint> points);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace penumbra
