#include "viz/planar_field.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace penumbra::viz {

namespace {

// How far a direction may be from a world axis and still be called that axis: grids are laid out
// in double precision from typed vectors, so aligned ones are aligned to round-off.
constexpr double kAxisTolerance = 1e-9;
// How far a point may be from its place in the lattice, relative to the grid's extent: the CSV
// holds exact doubles, so this only catches files that are not a lattice at all.
constexpr double kLatticeTolerance = 1e-6;

// The world axis (0, 1, 2) that `direction` runs along, positive or negative; -1 for none.
int worldAxisOf(const Vec3& direction) {
  const Vec3 d = direction.normalized();
  for (int i = 0; i < 3; ++i) {
    if (std::abs(std::abs(d[i]) - 1.0) < kAxisTolerance) return i;
  }
  return -1;
}

}  // namespace

PlotPlane plotPlaneFor(const PlanarField& f) {
  static constexpr std::array<const char*, 3> kNames{"x [m]", "y [m]", "z [m]"};
  PlotPlane plane;
  const int iu = worldAxisOf(f.uStep), iv = worldAxisOf(f.vStep);
  if (iu >= 0 && iv >= 0) {
    // World coordinates, z (when in the plane) up the picture, else x right and y up.
    int s = std::min(iu, iv), t = std::max(iu, iv);
    plane.origin = Vec3::Zero();
    plane.sAxis = Vec3::Unit(s);
    plane.tAxis = Vec3::Unit(t);
    plane.sLabel = kNames[s];
    plane.tLabel = kNames[t];
    return plane;
  }
  plane.sAxis = f.uStep.normalized();
  plane.tAxis = f.vStep.normalized();
  plane.origin = f.first - 0.5 * (f.uStep + f.vStep);  // the corner of the calculation area
  plane.sLabel = "u [m]";
  plane.tLabel = "v [m]";
  return plane;
}

namespace {

// A unit vector perpendicular to n.
Vec3 perpendicular(const Vec3& n) {
  const Vec3 helper = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (helper - helper.dot(n) * n).normalized();
}

}  // namespace

Eigen::Vector2d PlanarField::gridAt(const Eigen::Vector2d& st) const {
  const Vec3 w = plot.origin + st.x() * plot.sAxis + st.y() * plot.tAxis - first;
  return {w.dot(uStep) / uStep.squaredNorm(), w.dot(vStep) / vStep.squaredNorm()};
}

PlanarField planarField(const GridReport& grid) {
  if (grid.kind == GridKind::Points || grid.columns < 1 || grid.rows < 1) {
    throw std::invalid_argument(fmt::format("grid '{}' is not a planar grid", grid.name));
  }
  PlanarField f;
  f.name = grid.name;
  f.columns = grid.columns;
  f.rows = grid.rows;
  const std::size_t n = static_cast<std::size_t>(f.columns) * f.rows;
  if (grid.points.size() != n || grid.illuminance.size() != n || grid.insideSolids.size() != n) {
    throw std::invalid_argument(fmt::format("grid '{}': {} points for {} × {}", grid.name,
                                            grid.points.size(), f.columns, f.rows));
  }
  const auto at = [&](int c, int r) -> const Vec3& { return grid.points[f.index(c, r)].position; };
  f.first = at(0, 0);
  f.normal = grid.points[0].normal.normalized();
  const double spacing = grid.metrics.spacing > 0.0 ? grid.metrics.spacing : 1.0;
  if (f.columns > 1) f.uStep = (at(f.columns - 1, 0) - f.first) / (f.columns - 1);
  if (f.rows > 1) f.vStep = (at(0, f.rows - 1) - f.first) / (f.rows - 1);
  // A single row or column has one direction only; the other follows from u × v = normal.
  if (f.columns == 1 && f.rows == 1) {
    f.uStep = spacing * perpendicular(f.normal);
    f.vStep = spacing * f.normal.cross(f.uStep).normalized();
  } else if (f.columns == 1) {
    f.uStep = spacing * f.vStep.cross(f.normal).normalized();
  } else if (f.rows == 1) {
    f.vStep = spacing * f.normal.cross(f.uStep).normalized();
  }

  const double extent = (f.uStep * f.columns).norm() + (f.vStep * f.rows).norm();
  for (int r = 0; r < f.rows; ++r) {
    for (int c = 0; c < f.columns; ++c) {
      if ((at(c, r) - f.world(c, r)).norm() > kLatticeTolerance * extent) {
        throw std::invalid_argument(fmt::format(
            "grid '{}': point ({}, {}) is not on the lattice of its first row and column",
            grid.name, c, r));
      }
    }
  }
  f.illuminance = grid.illuminance;
  f.valid.reserve(n);
  for (const std::string& inside : grid.insideSolids) f.valid.push_back(inside.empty() ? 1 : 0);
  f.plot = plotPlaneFor(f);
  return f;
}

}  // namespace penumbra::viz
