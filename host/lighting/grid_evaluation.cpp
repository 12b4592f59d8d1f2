#include "lighting/grid_evaluation.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "geometry/tolerance.hpp"

namespace penumbra {

GridSamples gridSamples(const Scene& scene, const CalculationGrid& grid) {
  if (grid.positions.size() != grid.normals.size()) {
    throw std::invalid_argument("grid '" + grid.name + "': one normal per position is needed");
  }
  // Whether a grid point lies on a surface is a question about what a person typed (a sensor at
  // z = 0.75 on a desk top at 0.75): the input tolerance, relative to the scene's size, like the
  // loader's "on its wall" checks.
  const double tolerance = Tolerance::kRelativeInput * std::max(scene.size(), 1.0);
  GridSamples samples;
  samples.points.reserve(grid.positions.size());
  samples.inside.reserve(grid.positions.size());
  for (std::size_t i = 0; i < grid.positions.size(); ++i) {
    SamplePoint point;
    point.position = grid.positions[i];
    point.normal = grid.normals[i];
    int inside = -1;
    double bestAlignment = -2.0;
    for (int s = 0; s < static_cast<int>(scene.solids.size()); ++s) {
      const ConvexPolyhedron& shape = scene.solids[s].shape;
      if (shape.empty()) continue;
      // A point can lie on faces of two solids (the floor under a desk's foot). It lies on the
      // one whose face looks where the point looks: the other one must still be able to shade it.
      const int face = shape.faceContaining(point.position, point.normal, tolerance);
      if (face >= 0) {
        const double alignment = shape.faces()[face].plane.normal.dot(point.normal);
        if (alignment > bestAlignment) {
          bestAlignment = alignment;
          point.solid = s;
        }
      }
      if (inside < 0 && shape.containsStrictly(point.position, tolerance)) inside = s;
    }
    samples.points.push_back(point);
    samples.inside.push_back(inside);
  }
  return samples;
}

GridEvaluation evaluateGrid(const Scene& scene, const CalculationGrid& grid,
                            const IlluminanceEstimator& estimate, std::size_t batchSize,
                            const ProgressCallback& progress) {
  GridEvaluation evaluation;
  evaluation.name = grid.name;
  evaluation.samples = gridSamples(scene, grid);
  const auto& points = evaluation.samples.points;
  const auto& inside = evaluation.samples.inside;
  evaluation.illuminance.assign(points.size(), 0.0);

  // Only the points outside every solid go to the estimator; `index` maps them back.
  std::vector<SamplePoint> outside;
  std::vector<std::size_t> index;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (inside[i] >= 0) continue;
    outside.push_back(points[i]);
    index.push_back(i);
  }

  const auto start = std::chrono::steady_clock::now();
  batchSize = std::max<std::size_t>(batchSize, 1);
  const std::size_t skipped = points.size() - outside.size();
  if (progress) progress(skipped, points.size());
  for (std::size_t first = 0; first < outside.size(); first += batchSize) {
    const std::size_t count = std::min(batchSize, outside.size() - first);
    const std::vector<double> e =
        estimate(std::span<const SamplePoint>(outside).subspan(first, count));
    if (e.size() != count) throw std::logic_error("estimator returned the wrong number of values");
    for (std::size_t k = 0; k < count; ++k) evaluation.illuminance[index[first + k]] = e[k];
    if (progress) progress(skipped + first + count, points.size());
  }
  evaluation.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return evaluation;
}

}  // namespace penumbra
