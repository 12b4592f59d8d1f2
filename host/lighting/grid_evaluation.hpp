#pragma once
// From a calculation grid to illuminance at its points. The estimator is a parameter so that the
// kernel path (IlluminanceEngine) and the reference (referenceIlluminance) run through the same
// code; nothing here writes files (DESIGN.md), the output layer does.
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "lighting/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// The sample points of one grid in the grid's own order (row-major for planar grids, the order
// of the .res file), each with the solid it lies on, and the solid strictly containing it.
struct GridSamples {
  std::vector<SamplePoint> points;
  std::vector<int> inside;  // index into Scene::solids, -1 for none
};

GridSamples gridSamples(const Scene& scene, const CalculationGrid& grid);

// E in lx at each point.
using IlluminanceEstimator = std::function<std::vector<double>(std::span<const SamplePoint>)>;
// Called after each batch with the points of the grid done so far and the grid's total.
using ProgressCallback = std::function<void(std::size_t done, std::size_t total)>;

struct GridEvaluation {
  std::string name;
  GridSamples samples;
  std::vector<double> illuminance;  // lx, per point; 0 for points inside solids
  double seconds = 0.0;             // wall time spent in the estimator
};

// Evaluates the points that are not inside solids, `batchSize` at a time (so that progress can
// be reported), and gives E = 0 to the others.
GridEvaluation evaluateGrid(const Scene& scene, const CalculationGrid& grid,
                            const IlluminanceEstimator& estimate, std::size_t batchSize,
                            const ProgressCallback& progress = {});

}  // namespace penumbra
