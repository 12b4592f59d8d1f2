#pragma once
// A planar calculation grid as read back from its CSV, seen as a 2-D field: grid coordinates
// (a, b) count points along u and v from the first point; plot coordinates (s, t) are metres
// along the two axes of the picture.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "geometry/plane.hpp"
#include "grid/run_report.hpp"

namespace penumbra::viz {

// The picture's axes in the grid's plane. When the grid runs along world axes the plot shows
// world coordinates (a plan in x, y; an elevation in x, z or y, z); otherwise metres along the
// grid's own u and v from its corner.
struct PlotPlane {
  Vec3 origin = Vec3::Zero();  // the world point at (s, t) = (0, 0)
  Vec3 sAxis = Vec3::UnitX();  // unit, right on the picture
  Vec3 tAxis = Vec3::UnitY();  // unit, up on the picture
  std::string sLabel = "x [m]";
  std::string tLabel = "y [m]";

  Eigen::Vector2d project(const Vec3& world) const {
    return {sAxis.dot(world - origin), tAxis.dot(world - origin)};
  }
  Plane plane() const { return Plane::through(origin, sAxis.cross(tAxis)); }
};

struct PlanarField {
  std::string name;
  int columns = 0, rows = 0;
  Vec3 first = Vec3::Zero();  // point (0, 0)
  Vec3 uStep = Vec3::Zero();  // from point (c, r) to (c + 1, r), m
  Vec3 vStep = Vec3::Zero();  // from point (c, r) to (c, r + 1), m
  Vec3 normal = Vec3::UnitZ();
  std::vector<double> illuminance;  // lx, row-major as in the CSV
  std::vector<char> valid;          // 0 for points inside a solid (no E there)
  PlotPlane plot;

  std::size_t index(int c, int r) const { return static_cast<std::size_t>(r) * columns + c; }
  Vec3 world(double a, double b) const { return first + a * uStep + b * vStep; }
  Eigen::Vector2d plotAt(double a, double b) const { return plot.project(world(a, b)); }
  // Grid coordinates of a plot point (the inverse of plotAt).
  Eigen::Vector2d gridAt(const Eigen::Vector2d& st) const;
};

// The picture's axes for `field` (its lattice set): world axes when the grid runs along them.
PlotPlane plotPlaneFor(const PlanarField& field);

// Throws std::invalid_argument when the grid is not planar or its points are not a lattice.
PlanarField planarField(const GridReport& grid);

}  // namespace penumbra::viz
