#include "illuminance/estimator.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "engine/daylight_evaluation.hpp"
#include "illuminance/skylight.hpp"
#include "illuminance/sunlight.hpp"
#include "reference/reference_illuminance.hpp"
#include "scene/daylight.hpp"

namespace penumbra {

Estimator::Estimator(const EstimatorOptions& options, const Scene& scene) : scene_(&scene) {
  if (options.reference) {
    const int n = options.referenceN;
    if (n < 1) throw std::invalid_argument(fmt::format("--reference-n {}: must be at least 1", n));
    referenceN_ = n;
    name_ = "reference";
    device_ = fmt::format("host reference (double precision, n = {})", n);
    // About 2^24 samples per source face per batch: a progress step every fraction of a second
    // whatever n is.
    batchSize_ = std::clamp<std::size_t>((std::size_t{1} << 24) / (static_cast<std::size_t>(n) * n),
                                         1, 4096);
    return;
  }
  clDevice_.emplace(compute::Device::select(options.device));
  const compute::DeviceInfo& info = clDevice_->info();
  name_ = "kernel";
  device_ = fmt::format("{} ({}, {})", info.name, info.platform, info.type);
  engine_ = std::make_unique<IlluminanceEngine>(*clDevice_, scene, EngineOptions{options.culling});
  if (!options.culling) device_ += ", no culling";
  batchSize_ = 1 << 16;  // large enough to keep a GPU busy, small enough for progress
  withInterreflection_ = options.interreflection;
  culling_ = options.culling;
  mesh_ = options.mesh;
  solveInterreflection();
}

void Estimator::solveInterreflection() {
  interreflection_.reset();
  if (withInterreflection_) {
    HostLight host;
    const Scene* scene = scene_;
    if (skyOnHost(*scene_))
      host.sky = [scene](std::span<const SamplePoint> points) { return skylight(*scene, points); };
    if (scene_->sun)
      host.sun = [scene](std::span<const SamplePoint> points) { return sunlight(*scene, points); };
    interreflection_ = std::make_unique<Interreflection>(
        *clDevice_, *scene_, *engine_, mesh_, EngineOptions{culling_}, &transferCache_, host);
  }
}

Estimator::~Estimator() = default;

void Estimator::setScene(const Scene& scene) {
  scene_ = &scene;
  if (engine_) {
    engine_->setScene(scene);
    solveInterreflection();
  }
}

PointIlluminance Estimator::illuminance(std::span<const SamplePoint> points) {
  PointIlluminance e;
  if (!engine_) {
    e.total = daylightReference(*scene_, points);
  } else {
    // Without a sky, E alone: the shadow classes are neither downloaded nor reordered.
    e.total = scene_->sky ? evaluateDaylight(*engine_, *scene_, points).illuminance
                          : engine_->illuminance(points);
  }
  if (skyOnHost(*scene_)) {  // the sky past obstructions outside the room, on the host
    const std::vector<double> sky = skylight(*scene_, points);
    for (std::size_t i = 0; i < sky.size(); ++i) e.total[i] += sky[i];
  }
  if (interreflection_) {
    e.direct = e.total;
    InterreflectedIlluminance indirect = interreflection_->indirectParts(points);
    for (std::size_t i = 0; i < indirect.total.size(); ++i) e.total[i] += indirect.total[i];
    e.sunReflected = std::move(indirect.fromSun);
  }
  if (scene_->sun) {
    e.sun = sunlight(*scene_, points);
    for (std::size_t i = 0; i < e.sun.size(); ++i) e.total[i] += e.sun[i];
    for (std::size_t i = 0; i < e.direct.size(); ++i) e.direct[i] += e.sun[i];
  }
  return e;
}

std::vector<double> Estimator::interreflected(std::span<const SamplePoint> points) {
  if (!interreflection_) return std::vector<double>(points.size(), 0.0);
  return interreflection_->indirect(points);
}

std::vector<double> Estimator::daylightReference(const Scene& scene,
                                                 std::span<const SamplePoint> points) const {
  return estimateByGroup(scene, points, [&](const Scene& lit, std::span<const SamplePoint> p) {
    return referenceIlluminance(lit, p, referenceN_);
  });
}

IlluminanceEstimator Estimator::function() {
  return [this](std::span<const SamplePoint> points) { return illuminance(points); };
}

}  // namespace penumbra
