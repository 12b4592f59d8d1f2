#include "scene/scene.hpp"

#include <algorithm>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace penumbra {

CalculationGrid CalculationGrid::planar(std::string name, GridKind kind, const Vec3& origin,
                                        const Vec3& u, const Vec3& v, int columns, int rows,
                                        double spacing) {
  if (kind == GridKind::Points || columns < 1 || rows < 1) {
    throw std::invalid_argument("a planar grid needs a planar kind and at least 1 × 1 cells");
  }
  CalculationGrid grid;
  grid.name = std::move(name);
  grid.kind = kind;
  grid.spacing = spacing;
  grid.columns = columns;
  grid.rows = rows;
  grid.origin_ = origin;
  grid.u_ = u;
  grid.v_ = v;
  grid.planeNormal_ = u.cross(v).normalized();
  return grid;
}

CalculationGrid CalculationGrid::pointList(std::string name, std::vector<Vec3> positions,
                                           std::vector<Vec3> normals) {
  if (positions.size() != normals.size()) {
    throw std::invalid_argument("grid '" + name + "': one normal per position is needed");
  }
  CalculationGrid grid;
  grid.name = std::move(name);
  grid.kind = GridKind::Points;
  grid.positions_ = std::move(positions);
  grid.normals_ = std::move(normals);
  return grid;
}

std::size_t CalculationGrid::size() const {
  if (kind == GridKind::Points) return positions_.size();
  return static_cast<std::size_t>(columns) * static_cast<std::size_t>(rows);
}

Vec3 CalculationGrid::position(std::size_t i) const {
  if (kind == GridKind::Points) return positions_[i];
  const int column = static_cast<int>(i % static_cast<std::size_t>(columns));
  const int row = static_cast<int>(i / static_cast<std::size_t>(columns));
  return origin_ + (column + 0.5) / columns * u_ + (row + 0.5) / rows * v_;
}

Vec3 CalculationGrid::normal(std::size_t i) const {
  return kind == GridKind::Points ? normals_[i] : planeNormal_;
}

std::string skyModelName(SkyModel model) {
  switch (model) {
    case SkyModel::Uniform:
      return "uniform";
    case SkyModel::CieOvercast:
      return "cie-overcast";
    case SkyModel::CieGeneral:
      return "cie-general";
  }
  return "unknown";
}

double Sky::zenithLuminance() const {
  return model == SkyModel::CieOvercast ? 9.0 * horizontalIlluminance / (7.0 * std::numbers::pi)
                                        : horizontalIlluminance / std::numbers::pi;
}

double Sky::groundLuminance() const {
  return groundReflectance * horizontalIlluminance / std::numbers::pi;
}

double Source::emittingArea() const {
  double area = 0.0;
  for (const ConvexPolygon& face : faces) area += face.area();
  return area;
}

BoundingBox Scene::geometryBounds() const {
  BoundingBox box;
  const auto add = [&](const Vec3& p) { box.add(p); };
  for (const Solid& solid : solids)
    std::for_each(solid.shape.vertices().begin(), solid.shape.vertices().end(), add);
  for (const Source& source : sources) {
    for (const ConvexPolygon& face : source.faces) {
      std::for_each(face.vertices().begin(), face.vertices().end(), add);
    }
  }
  for (const Luminaire& luminaire : luminaires) {
    for (const LuminaireInstance& instance : luminaire.instances) add(instance.position);
  }
  return box;
}

BoundingBox Scene::bounds() const {
  // Calculation points count as geometry here: the tolerance derived from this size must also
  // be fine enough for them (a grid may reach beyond every solid, or a scene may have no solid).
  BoundingBox box = geometryBounds();
  const auto add = [&](const Vec3& p) { box.add(p); };
  for (const CalculationGrid& grid : grids) {
    if (grid.kind == GridKind::Points) {
      for (std::size_t i = 0; i < grid.size(); ++i) add(grid.position(i));
      continue;
    }
    // A planar grid's points are an affine image of the cell indices and rounding is monotonic:
    // the four corner points span the same box as all of them.
    const std::size_t c = static_cast<std::size_t>(grid.columns),
                      r = static_cast<std::size_t>(grid.rows);
    for (std::size_t i : {std::size_t{0}, c - 1, (r - 1) * c, r * c - 1}) add(grid.position(i));
  }
  return box;
}

Vec3 Scene::kernelOrigin() const {
  BoundingBox box = geometryBounds();
  if (box.empty()) box = bounds();
  return box.empty() ? Vec3::Zero() : Vec3(0.5 * (box.lo + box.hi));
}

double Scene::size() const {
  const BoundingBox box = bounds();
  return box.empty() ? 0.0 : (box.hi - box.lo).norm();
}

}  // namespace penumbra
