#include "reference/luminaire_illuminance.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "geometry/tolerance.hpp"
#include "reference/opening_illuminance.hpp"
#include "reference/reference_occluders.hpp"

namespace penumbra {
namespace {

struct Shading {
  std::vector<reference::Occluder> occluders;
  double tolerance = 0.0;

  bool seen(const SamplePoint& point, const Vec3& centre) const {
    for (const reference::Occluder& o : occluders) {
      if (o.solid == point.solid) continue;
      if (reference::segmentBlocked(o, point.position, centre, tolerance)) return false;
    }
    return true;
  }
};

// I(ω) · cos θ / d² from a point source at `centre` carrying `share` of the luminaire's
// intensity; 0 behind the point's surface or shaded.
double pointIlluminance(const Luminaire& luminaire, const LuminaireInstance& instance,
                        const Vec3& centre, double share, const Shading& shading,
                        const SamplePoint& point) {
  const Vec3 towardsCentre = centre - point.position;
  const double d2 = towardsCentre.squaredNorm();
  if (d2 == 0.0) return 0.0;
  const double d = std::sqrt(d2);
  const double cosTheta = point.normal.normalized().dot(towardsCentre) / d;
  if (cosTheta <= 0.0 || !shading.seen(point, centre)) return 0.0;
  const Vec3 local = instance.toScene.transpose() * (-towardsCentre);
  return share * luminaire.intensity(local) * cosTheta / d2;
}

double instanceIlluminance(const Scene& scene, const Shading& shading, const Luminaire& luminaire,
                           const LuminaireInstance& instance, const SamplePoint& point) {
  if (luminaire.model == LuminaireModel::Point || !luminaire.opening)
    return pointIlluminance(luminaire, instance, instance.position, 1.0, shading, point);
  const LuminaireOpening& opening = *luminaire.opening;
  if (!opening.subdivided())
    return openingIlluminance(luminaire, instance, point, scene, shading.tolerance);
  const double share = 1.0 / (opening.partsAlongLength * opening.partsAlongWidth);
  double sum = 0.0;
  for (int j = 0; j < opening.partsAlongWidth; ++j)
    for (int i = 0; i < opening.partsAlongLength; ++i)
      sum += pointIlluminance(luminaire, instance,
                              instance.position + instance.toScene * opening.partCentre(i, j),
                              share, shading, point);
  return sum;
}

double illuminanceAt(const Scene& scene, const Shading& shading, const SamplePoint& point) {
  double total = 0.0;
  for (const Luminaire& luminaire : scene.luminaires)
    for (const LuminaireInstance& instance : luminaire.instances)
      total += instanceIlluminance(scene, shading, luminaire, instance, point);
  return total;
}

}  // namespace

std::vector<double> referenceLuminaireIlluminance(const Scene& scene,
                                                  std::span<const SamplePoint> points) {
  std::vector<double> result(points.size(), 0.0);
  if (scene.luminaires.empty()) return result;
  Shading shading;
  shading.tolerance = Tolerance::forSceneSize(scene.size()).length;
  shading.occluders = reference::buildOccluders(scene, shading.tolerance);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 64),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i < r.end(); ++i)
                        result[i] = illuminanceAt(scene, shading, points[i]);
                    });
  return result;
}

}  // namespace penumbra
