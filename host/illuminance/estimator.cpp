#include "illuminance/estimator.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "engine/daylight_evaluation.hpp"
#include "illuminance/host_daylight.hpp"
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
    interreflection_ = std::make_unique<Interreflection>(*clDevice_, *scene_, *engine_, mesh_,
                                                         EngineOptions{culling_}, &transferCache_,
                                                         hostDaylight(*scene_));
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

std::vector<double> Estimator::directDaylight(std::span<const SamplePoint> points,
                                              std::vector<double>* ground) {
  std::vector<double> total;
  if (ground) ground->assign(points.size(), 0.0);
  if (!engine_) {
    total = daylightReference(*scene_, points);
  } else if (!scene_->sky) {
    // Without a sky, E alone: the shadow classes are neither downloaded nor reordered.
    total = engine_->illuminance(points);
  } else {
    const IlluminanceResult result =
        evaluateDaylight(*engine_, *scene_, points, ground != nullptr && !skyOnHost(*scene_));
    total = result.illuminance;
    if (!result.bySource.empty()) {
      // daylightScene's sources: the scene's own, then a sky and a ground source per opening.
      const std::size_t sources = static_cast<std::size_t>(result.sourceCount);
      for (std::size_t s = scene_->sources.size() + 1; s < sources; s += 2)
        for (std::size_t i = 0; i < points.size(); ++i)
          (*ground)[i] += result.bySource[i * sources + s];
    }
  }
  if (skyOnHost(*scene_)) {  // the sky past obstructions outside the room, on the host
    const SkylightParts sky = skylightParts(*scene_, points);
    for (std::size_t i = 0; i < sky.total.size(); ++i) total[i] += sky.total[i];
    if (ground) *ground = sky.ground;
  }
  return total;
}

PointIlluminance Estimator::illuminance(std::span<const SamplePoint> points) {
  PointIlluminance e;
  const bool components = interreflection_ && scene_->sky;
  std::vector<double> ground;
  e.total = directDaylight(points, components ? &ground : nullptr);
  std::vector<double> outsideReflected;
  if (interreflection_) {
    e.direct = e.total;
    InterreflectedIlluminance indirect = interreflection_->indirectParts(points);
    for (std::size_t i = 0; i < indirect.total.size(); ++i) e.total[i] += indirect.total[i];
    e.sunReflected = std::move(indirect.fromSun);
    outsideReflected = std::move(indirect.fromOutside);
  }
  if (components) {
    e.skyComponent.resize(points.size());
    e.externalComponent = std::move(ground);
    for (std::size_t i = 0; i < points.size(); ++i)
      e.skyComponent[i] = e.direct[i] - e.externalComponent[i];
    for (std::size_t i = 0; i < outsideReflected.size(); ++i)
      e.externalComponent[i] += outsideReflected[i];
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
