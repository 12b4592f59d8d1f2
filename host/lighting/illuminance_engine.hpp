#pragma once
// Exact direct illuminance at sample points, computed by kernels/illuminance.cl.
#include <memory>
#include <span>
#include <vector>

#include "cl/device.hpp"
#include "lighting/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

class IlluminanceEngine {
 public:
  // Builds the program and uploads the scene (sources, occluders clipped to each source's
  // front half-space) once; illuminance() may then be called many times.
  IlluminanceEngine(compute::Device& device, const Scene& scene);
  ~IlluminanceEngine();

  // E in lx at every point, summed over all sources.
  std::vector<double> illuminance(std::span<const SamplePoint> points);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace penumbra
