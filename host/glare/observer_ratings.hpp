#pragma once
// Every observer of a scene rated along each of its lines of sight (glare_rating.hpp), with the
// background luminance from the indirect illuminance at each eye.
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "geometry/sample_point.hpp"
#include "glare/glare_rating.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// The indirect (interreflected) illuminance in lx at each point, on the plane of its normal;
// zeros for a run without interreflection.
using IndirectIlluminance = std::function<std::vector<double>(std::span<const SamplePoint>)>;

struct ObserverRating {
  const Observer* observer = nullptr;
  std::vector<GlareRating> views;  // one per observer->looks, in order
  // The largest UGR over the views; nothing when no view has one.
  std::optional<double> ugrMax() const;
};

// The largest UGR over every observer and line of sight; nothing when none has one.
std::optional<double> highestUgr(const std::vector<ObserverRating>& ratings);

// The eye's points, one per line of sight, each facing along it: where L_b is measured.
std::vector<SamplePoint> backgroundPoints(const Observer& observer);

// Every observer of `scene`, in scene order. L_b = E_ind/π at backgroundPoints.
std::vector<ObserverRating> rateObservers(const Scene& scene, const IndirectIlluminance& indirect);

}  // namespace penumbra
