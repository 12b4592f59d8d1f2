#pragma once
// From a calculation grid to illuminance at its points. The estimator is a parameter so that the
// kernel path (IlluminanceEngine) and the reference (referenceIlluminance) run through the same
// code; nothing here writes files, the output layer does.
//
// A grid is evaluated in batches and its results are handed on batch by batch (streamGrid), so
// that a grid of 10^7 points needs the memory of one batch, not of the grid: the points of a
// batch are generated from the grid's description, classified against the solids, estimated and
// dropped. evaluateGrid keeps everything, for tests and for callers that want it all at once.
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "geometry/bounding_box.hpp"
#include "geometry/sample_point.hpp"
#include "grid/grid_metrics.hpp"
#include "illuminance/estimator.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// Finds the solid a point lies on and the solid strictly containing it. The solids' boxes are
// binned in a uniform lattice of cells, so that a point tests only the few solids whose box
// reaches its cell: a scene of 10^4 solids costs a point about what a scene of ten does.
// The answers are those of testing every solid in order (the box of a solid is grown so that
// it holds every point either test can accept; see the .cpp).
class SolidLocator {
 public:
  explicit SolidLocator(const Scene& scene);
  // Sets point.solid (the solid whose face the point lies on, the one facing where the point
  // looks when it touches several; -1 for none) and returns the first solid, in scene order,
  // that strictly contains the point (-1 for none).
  int classify(SamplePoint& point) const;
  // classify for each of a run of nearby points (their positions and normals set), inside[k]
  // its answer: the same answers, the solids that can hold any of them found once for the run.
  void classify(std::span<SamplePoint> points, std::span<int> inside) const;

 private:
  std::span<const int> candidates(const Vec3& p) const;
  // Sets point.solid and returns the containing solid, testing `solids` (ascending) only.
  int classifyAmong(SamplePoint& point, std::span<const int> solids) const;

  const Scene* scene_;
  double tolerance_ = 0.0;
  std::vector<BoundingBox> boxes_;  // per solid: every point either test can accept
  BoundingBox bounds_;              // of all finite boxes
  int cells_[3] = {1, 1, 1};
  std::vector<std::vector<int>> cellSolids_;  // per cell, ascending solid indices
  std::vector<int> unbounded_;                // solids whose box could not be bounded
  std::vector<int> tested_;                   // every solid with a shape, ascending
};

// The sample points of one grid in the grid's own order (row-major for planar grids, the order
// of the .res file), each with the solid it lies on, and the solid strictly containing it.
struct GridSamples {
  std::vector<SamplePoint> points;
  std::vector<int> inside;  // index into Scene::solids, -1 for none

  // The points that lie inside no solid (those whose E is computed), in the grid's order.
  std::vector<SamplePoint> outsideSolids() const;
};

// Grid points [first, first + count), count clipped to the grid's end.
GridSamples gridSamples(const SolidLocator& solids, const CalculationGrid& grid,
                        std::size_t first = 0,
                        std::size_t count = std::numeric_limits<std::size_t>::max());
GridSamples gridSamples(const Scene& scene, const CalculationGrid& grid);

// Called after each batch with the points of the grid done so far and the grid's total.
using ProgressCallback = std::function<void(std::size_t done, std::size_t total)>;

// Consecutive grid points [first, first + illuminance.size()) with their results, handed on in
// grid order as soon as they are known.
struct GridBatch {
  std::size_t first = 0;
  std::span<const double> illuminance;  // lx, total; 0 for points inside solids
  std::span<const double> direct;       // lx, its direct part; empty for a direct-only run
  std::span<const double> sun;          // lx, the direct sunlight in E; empty without a sun
  // lx, the sun's light reflected by the room, part of E (not of direct); empty without a sun or
  // for a direct-only run
  std::span<const double> sunReflected;
  // lx, the sky and the externally reflected components of the daylight (PointIlluminance);
  // empty without a sky or for a direct-only run
  std::span<const double> skyComponent, externalComponent;
  std::span<const int> inside;   // index into Scene::solids, -1 for none
  std::span<const int> onSolid;  // the solid each point lies on, -1 for none
};
using GridBatchSink = std::function<void(const GridBatch&)>;

// What is left of a streamed grid: its metrics (gridMetrics over every point, in order) and the
// time spent evaluating it.
struct GridRun {
  std::string name;
  GridMetrics metrics;                       // of the total
  std::optional<GridMetrics> directMetrics;  // of the direct part, when interreflection is on
  // When the scene has a sky: the daylight factor of E less the sun's parts (DF is defined under
  // the overcast sky); the EN 17037 verdict only for a grid facing up (a horizontal reference
  // plane).
  std::optional<DaylightMetrics> daylight;
  std::optional<SunMetrics> sun;  // when the scene has a sun
  double seconds = 0.0;           // wall time: classifying points and the estimator
};

// Whether every point of `grid` faces straight up (+z): a horizontal reference plane.
bool facesUp(const CalculationGrid& grid);

// Evaluates the points that are not inside solids, `batchSize` at a time (the estimator sees the
// same batches whatever the sink does), gives E = 0 to the others, and hands every point to
// `sink` in grid order. The points are classified in parallel, a block of 4096 at a time ahead
// of the batch that takes them. Memory: one batch of points and the inside points between them;
// with a sky, also two doubles per point (E and its direct part, for the median daylight factor).
GridRun streamGrid(const Scene& scene, const CalculationGrid& grid,
                   const IlluminanceEstimator& estimate, std::size_t batchSize,
                   const GridBatchSink& sink, const ProgressCallback& progress = {});

struct GridEvaluation {
  std::string name;
  GridSamples samples;
  std::vector<double> illuminance;   // lx, per point, total; 0 for points inside solids
  std::vector<double> direct;        // lx, its direct part; empty for a direct-only run
  std::vector<double> sun;           // lx, the direct sunlight in E; empty without a sun
  std::vector<double> sunReflected;  // lx, the sun's light reflected by the room, part of E
  // lx, the sky and the externally reflected components (GridBatch); empty without them
  std::vector<double> skyComponent, externalComponent;
  GridMetrics metrics;
  std::optional<DaylightMetrics> daylight;  // when the scene has a sky
  std::optional<SunMetrics> sunMetrics;     // when the scene has a sun
  double seconds = 0.0;
};

// streamGrid, keeping every point and value.
GridEvaluation evaluateGrid(const Scene& scene, const CalculationGrid& grid,
                            const IlluminanceEstimator& estimate, std::size_t batchSize,
                            const ProgressCallback& progress = {});

}  // namespace penumbra
