#pragma once
// Primary visibility on the device (kernels/visibility.cl): the face each sample of a camera
// sees, and how far along its ray.
#include <cstdint>
#include <memory>
#include <vector>

#include "cl/device.hpp"
#include "render/camera.hpp"
#include "render/visible_scene.hpp"

namespace penumbra {

struct VisibilityImage {
  int width = 0, height = 0;
  std::vector<uint32_t> faceIds;      // per sample, row-major; 0 = nothing
  std::vector<float> t;               // hit = eye + t·camera.direction(x, y); 0 where nothing
  double objectTestsPerSample = 0.0;  // mean length of the tile lists the samples scanned
};

class VisibilityEngine {
 public:
  // Builds the program and uploads `scene`'s visible objects.
  VisibilityEngine(compute::Device& device, const Scene& scene);
  ~VisibilityEngine();
  void setScene(const Scene& scene);  // keeps the program, as a sweep does between cases

  const VisibleScene& visible() const;
  VisibilityImage trace(const Camera& camera);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace penumbra
