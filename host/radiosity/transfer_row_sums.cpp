#include "radiosity/transfer_row_sums.hpp"

#include <numbers>
#include <string>

#include "engine/illuminance_engine.hpp"
#include "illuminance/skylight.hpp"
#include "scene/daylight.hpp"

namespace penumbra {

std::optional<Scene> unseenByElements(const Scene& scene) {
  if (!scene.room) return std::nullopt;
  Scene unseen = solidsOf(scene);
  for (const Solid& solid : scene.solids) {
    if (reflectsLight(scene, solid)) continue;
    for (int f = 0; f < static_cast<int>(solid.shape.faces().size()); ++f) {
      Source face;
      face.name = solid.name + ".face-" + std::to_string(f);
      face.faces = {solid.shape.facePolygon(f)};
      face.luminance = 1.0;
      unseen.sources.push_back(std::move(face));
    }
  }
  if (solidReachesOutsideRoom(scene)) return unseen;
  for (const Opening& opening : scene.room->openings) {
    Source world;
    world.name = opening.name + ".beyond";
    world.faces = {opening.outer};
    world.luminance = 1.0;
    unseen.sources.push_back(std::move(world));
  }
  return unseen;
}

std::optional<Scene> worldBeyond(const Scene& scene) {
  if (!scene.room) return std::nullopt;
  Scene world = solidsOf(scene);
  for (Opening& opening : world.room->openings) opening.transmittance = 1.0;
  Sky sky;
  sky.model = SkyModel::Uniform;
  sky.horizontalIlluminance = std::numbers::pi;  // L = E_h/π = 1 cd/m²
  sky.groundReflectance = 1.0;                   // L = ρ_g·E_h/π = 1 cd/m²
  world.sky = sky;
  return world;
}

std::optional<Eigen::VectorXd> transferRowSums(compute::Device& device, const Scene& scene,
                                               const SurfaceMesh& mesh,
                                               const EngineOptions& options) {
  const std::optional<Scene> unseen = unseenByElements(scene);
  if (!unseen) return std::nullopt;
  const auto n = static_cast<Eigen::Index>(mesh.elements.size());
  Eigen::VectorXd sums = Eigen::VectorXd::Constant(n, std::numbers::pi);
  if (n == 0) return sums;
  std::vector<double> e(mesh.nodes.size(), 0.0);
  if (!unseen->sources.empty()) {
    IlluminanceEngine engine(device, *unseen, options);
    e = engine.illuminance(mesh.nodes);
  }
  if (solidReachesOutsideRoom(scene)) {
    const std::vector<double> world = surfaceSkylight(*worldBeyond(scene), mesh.nodes);
    for (std::size_t k = 0; k < e.size(); ++k) e[k] += world[k];
  }
  for (Eigen::Index i = 0; i < n; ++i)
    for (std::size_t k = mesh.nodeStart[i]; k < mesh.nodeStart[i + 1]; ++k)
      sums[i] -= mesh.weights[k] * e[k];
  return sums;
}

}  // namespace penumbra
