#include "glare/observer_ratings.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <numbers>

namespace penumbra {

std::optional<double> ObserverRating::ugrMax() const {
  std::optional<double> highest;
  for (const GlareRating& view : views) {
    if (view.ugr && (!highest || *view.ugr > *highest)) highest = view.ugr;
  }
  return highest;
}

std::optional<double> highestUgr(const std::vector<ObserverRating>& ratings) {
  std::optional<double> highest;
  for (const ObserverRating& rating : ratings) {
    const std::optional<double> max = rating.ugrMax();
    if (max && (!highest || *max > *highest)) highest = max;
  }
  return highest;
}

std::vector<SamplePoint> backgroundPoints(const Observer& observer) {
  std::vector<SamplePoint> points;
  for (const Vec3& look : observer.looks) points.push_back(SamplePoint{observer.eye, look, -1});
  return points;
}

std::vector<ObserverRating> rateObservers(const Scene& scene, const IndirectIlluminance& indirect) {
  std::vector<SamplePoint> points;
  for (const Observer& observer : scene.observers) {
    const std::vector<SamplePoint> own = backgroundPoints(observer);
    points.insert(points.end(), own.begin(), own.end());
  }
  const std::vector<double> background = points.empty() ? std::vector<double>{} : indirect(points);
  std::vector<std::size_t> first(scene.observers.size(), 0);
  for (std::size_t i = 1; i < first.size(); ++i)
    first[i] = first[i - 1] + scene.observers[i - 1].looks.size();

  std::vector<ObserverRating> ratings(scene.observers.size());
  tbb::parallel_for(std::size_t{0}, scene.observers.size(), [&](std::size_t i) {
    const Observer& observer = scene.observers[i];
    const EyeView seen = seenSources(scene, observer.eye);
    ratings[i].observer = &observer;
    for (std::size_t k = 0; k < observer.looks.size(); ++k) {
      const double backgroundLuminance = std::max(background[first[i] + k], 0.0) / std::numbers::pi;
      ratings[i].views.push_back(rateView(seen, observer.looks[k], backgroundLuminance));
    }
  });
  return ratings;
}

}  // namespace penumbra
