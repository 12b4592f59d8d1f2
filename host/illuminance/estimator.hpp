#pragma once
// The illuminance of a run: the direct part from the exact OpenCL kernel on a device
// (engine/IlluminanceEngine) or from the host reference, plus the interreflected part
// (radiosity/Interreflection, the sun's light included) unless the run asks for direct light
// only, plus the direct sunlight of a scene with a sun (sunlight.hpp, on the host in double for
// either estimator). A sky with obstructions outside the room is computed on the host too
// (skylight.hpp, for either estimator), and interreflected. `penumbra grid` makes
// one per run; `penumbra sweep` keeps one for all its cases (the device and the compiled
// program stay, only the scene is replaced), so both compute through this class.
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cl/device.hpp"
#include "engine/illuminance_engine.hpp"
#include "geometry/sample_point.hpp"
#include "radiosity/interreflection.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// E in lx at each point: the total, its direct part where interreflection is computed, and the
// direct sunlight it holds where the scene has a sun.
struct PointIlluminance {
  std::vector<double> total;   // lx
  std::vector<double> direct;  // lx; empty when the total is direct light only
  std::vector<double> sun;     // lx, part of total and of direct; empty without a sun
  // lx, the sun's light reflected by the room: part of total, not of direct; empty without a
  // sun or without interreflection
  std::vector<double> sunReflected;
  // With a sky and interreflection, the daylight's split into the BRE components (lx, the sun
  // left out; docs/method.md, "Daylight factor components"); empty otherwise:
  //   skyComponent       the direct light but the sun's and the ground's: the sky seen through
  //                      the openings (and the direct light of the scene's own sources)
  //   externalComponent  the ground seen through the openings, plus what the faces outside the
  //                      room reflect straight to the point (their light from the sky and ground)
  // The internally reflected component is the rest, total − sun − sunReflected − both.
  std::vector<double> skyComponent;
  std::vector<double> externalComponent;
  PointIlluminance() = default;
  PointIlluminance(std::vector<double> directOnly) : total(std::move(directOnly)) {}  // NOLINT
};

// The estimator of a run as grid evaluation takes it: the kernel (with or without
// interreflection) or the host reference, through one signature.
using IlluminanceEstimator = std::function<PointIlluminance(std::span<const SamplePoint>)>;

struct EstimatorOptions {
  std::string device = "auto";  // "auto", "cpu", "gpu" or an index from `penumbra devices`
  bool reference = false;       // the host reference instead of the OpenCL kernel (direct only)
  int referenceN = 64;          // reference: ~n² sub-elements per source face
  bool culling = true;          // kernel: shadow-volume culling; off: every occluder at every point
  bool interreflection = true;  // kernel: add the interreflected light; off: direct only
  MeshOptions mesh;             // the elements of the interreflection
};

class Estimator {
 public:
  // Opens the device and builds the program (kernel), or checks n (reference); with
  // interreflection, solves it for `scene`. Throws std::invalid_argument for n < 1 and
  // std::runtime_error when no device fits. `scene` must outlive every call until the next
  // setScene.
  Estimator(const EstimatorOptions& options, const Scene& scene);
  ~Estimator();
  Estimator(const Estimator&) = delete;
  Estimator& operator=(const Estimator&) = delete;

  // Answers for `scene` from now on (same lifetime rule); the device and program are kept, the
  // interreflection is solved again.
  void setScene(const Scene& scene);

  // E at every point: the total, with its direct part when interreflection is on and the sun's
  // part when the scene has a sun.
  PointIlluminance illuminance(std::span<const SamplePoint> points);
  // The interreflected part of E alone (lx); zeros when the run is direct light only.
  std::vector<double> interreflected(std::span<const SamplePoint> points);
  // The same as the callable that evaluateGrid takes.
  IlluminanceEstimator function();

  std::size_t batchSize() const { return batchSize_; }   // points per call, for progress
  const std::string& name() const { return name_; }      // "kernel" or "reference"
  const std::string& device() const { return device_; }  // in words
  int referenceN() const { return referenceN_; }         // 0 for the kernel
  // The solver's report; null when the run is direct light only.
  const InterreflectionReport* interreflection() const {
    return interreflection_ ? &interreflection_->report() : nullptr;
  }

 private:
  void solveInterreflection();
  // E of the kernel's sources and luminaires and of the host's sky at `points`, with the ground
  // seen through the openings in `ground` when it is given (interreflected runs with a sky).
  std::vector<double> directDaylight(std::span<const SamplePoint> points,
                                     std::vector<double>* ground);
  // The host reference at `points`, through the sky's groups when the scene has one.
  std::vector<double> daylightReference(const Scene& scene,
                                        std::span<const SamplePoint> points) const;

  const Scene* scene_;
  int referenceN_ = 0;
  std::size_t batchSize_ = 1;
  std::string name_;
  std::string device_;
  bool withInterreflection_ = false;
  bool culling_ = true;
  MeshOptions mesh_;
  std::optional<compute::Device> clDevice_;
  std::unique_ptr<IlluminanceEngine> engine_;
  TransferCache transferCache_;  // kept across setScene: a sweep's cases share transfers
  std::unique_ptr<Interreflection> interreflection_;
};

}  // namespace penumbra
