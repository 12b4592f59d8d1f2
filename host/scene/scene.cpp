#include "scene/scene.hpp"

#include <algorithm>
#include <limits>

namespace penumbra {

double Source::emittingArea() const {
  double area = 0.0;
  for (const ConvexPolygon& face : faces) area += face.area();
  return area;
}

double Scene::size() const {
  // Calculation points count as geometry here: the tolerance derived from this size must also
  // be fine enough for them (a grid may reach beyond every solid, or a scene may have no solid).
  Vec3 low = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 high = -low;
  const auto add = [&](const Vec3& p) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  };
  for (const Solid& solid : solids)
    std::for_each(solid.shape.vertices().begin(), solid.shape.vertices().end(), add);
  for (const Source& source : sources) {
    for (const ConvexPolygon& face : source.faces) {
      std::for_each(face.vertices().begin(), face.vertices().end(), add);
    }
  }
  for (const CalculationGrid& grid : grids)
    std::for_each(grid.positions.begin(), grid.positions.end(), add);
  return (high.array() >= low.array()).all() ? (high - low).norm() : 0.0;
}

}  // namespace penumbra
