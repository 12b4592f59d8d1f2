#pragma once
// The illuminance estimator of a run: the exact OpenCL kernel on a device, or the host reference.
// `penumbra grid` makes one per run; `penumbra sweep` keeps one for all its cases (the device and
// the compiled program stay, only the scene is replaced), so both compute through this class.
#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cl/device.hpp"
#include "lighting/grid_evaluation.hpp"
#include "lighting/illuminance_engine.hpp"
#include "lighting/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct EstimatorOptions {
  std::string device = "auto";  // "auto", "cpu", "gpu" or an index from `penumbra devices`
  bool reference = false;       // the host reference instead of the OpenCL kernel
  int referenceN = 64;          // reference: ~n² sub-elements per source face
  bool culling = true;          // kernel: shadow-volume culling; off = the plain path
};

class Estimator {
 public:
  // Opens the device and builds the program (kernel), or checks n (reference). Throws
  // std::invalid_argument for n < 1 and std::runtime_error when no device fits. `scene` must
  // outlive every call until the next setScene.
  Estimator(const EstimatorOptions& options, const Scene& scene);
  ~Estimator();
  Estimator(const Estimator&) = delete;
  Estimator& operator=(const Estimator&) = delete;

  // Answers for `scene` from now on (same lifetime rule); the device and program are kept.
  void setScene(const Scene& scene);

  // E in lx at every point, summed over all sources.
  std::vector<double> illuminance(std::span<const SamplePoint> points);
  // The same as the callable that evaluateGrid takes.
  IlluminanceEstimator function();

  std::size_t batchSize() const { return batchSize_; }   // points per call, for progress
  const std::string& name() const { return name_; }      // "kernel" or "reference"
  const std::string& device() const { return device_; }  // in words
  int referenceN() const { return referenceN_; }         // 0 for the kernel

 private:
  const Scene* scene_;
  int referenceN_ = 0;
  std::size_t batchSize_ = 1;
  std::string name_;
  std::string device_;
  std::optional<compute::Device> clDevice_;
  std::unique_ptr<IlluminanceEngine> engine_;
};

}  // namespace penumbra
