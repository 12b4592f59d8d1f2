#include "reference/luminaire_illuminance.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "geometry/tolerance.hpp"
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

double illuminanceAt(const Scene& scene, const Shading& shading, const SamplePoint& point) {
  const Vec3 n = point.normal.normalized();
  double total = 0.0;
  for (const Luminaire& luminaire : scene.luminaires) {
    for (const LuminaireInstance& instance : luminaire.instances) {
      const Vec3 towardsCentre = instance.position - point.position;
      const double d2 = towardsCentre.squaredNorm();
      if (d2 == 0.0) continue;
      const double d = std::sqrt(d2);
      const double cosTheta = n.dot(towardsCentre) / d;
      if (cosTheta <= 0.0 || !shading.seen(point, instance.position)) continue;
      const Vec3 local = instance.toScene.transpose() * (-towardsCentre);
      total += luminaire.intensity(local) * cosTheta / d2;
    }
  }
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
