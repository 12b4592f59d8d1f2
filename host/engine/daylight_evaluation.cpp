#include "engine/daylight_evaluation.hpp"

#include "scene/daylight.hpp"

namespace penumbra {

namespace {

// Copies the per-point rows of `part` (for the group's points) into `all` at the points' places.
template <typename T>
void scatterRows(const std::vector<T>& part, std::size_t width, const DaylightGroup& group,
                 std::vector<T>& all) {
  if (part.empty()) return;
  for (std::size_t j = 0; j < group.points.size(); ++j)
    for (std::size_t k = 0; k < width; ++k) all[group.points[j] * width + k] = part[j * width + k];
}

}  // namespace

IlluminanceResult evaluateDaylight(IlluminanceEngine& engine, const Scene& scene,
                                   std::span<const SamplePoint> points, bool bySource) {
  if (!scene.sky) return engine.evaluate(points, bySource);
  IlluminanceResult all;
  const std::vector<DaylightGroup> groups = daylightGroups(scene, points);
  bool first = true;
  for (const DaylightGroup& group : groups) {
    engine.setScene(daylightScene(scene, group.height));
    const std::vector<SamplePoint> subset = groupPoints(group, points);
    const IlluminanceResult part = engine.evaluate(subset, bySource);
    if (first) {  // every group has the same sources and luminaires
      all.sourceCount = part.sourceCount;
      all.luminaireCount = part.luminaireCount;
      const std::size_t n = points.size();
      const auto sources = static_cast<std::size_t>(part.sourceCount);
      const auto luminaires = static_cast<std::size_t>(part.luminaireCount);
      all.illuminance.assign(n, 0.0);
      all.shadowClass.resize(part.shadowClass.empty() ? 0 : n * sources);
      all.bySource.assign(part.bySource.empty() ? 0 : n * sources, 0.0);
      all.luminaires.assign(part.luminaires.empty() ? 0 : n, 0.0);
      all.luminaireShadow.resize(part.luminaireShadow.empty() ? 0 : n * luminaires);
      first = false;
    }
    const auto sources = static_cast<std::size_t>(part.sourceCount);
    scatterRows(part.illuminance, 1, group, all.illuminance);
    scatterRows(part.shadowClass, sources, group, all.shadowClass);
    scatterRows(part.bySource, sources, group, all.bySource);
    scatterRows(part.luminaires, 1, group, all.luminaires);
    scatterRows(part.luminaireShadow, static_cast<std::size_t>(part.luminaireCount), group,
                all.luminaireShadow);
  }
  return all;
}

}  // namespace penumbra
