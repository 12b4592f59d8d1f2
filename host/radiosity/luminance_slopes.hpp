#pragma once
// The final gather's reflected luminance, linear over each element. The solve gives each element
// its mean luminance; taken as uniform over the element, the gather at a point errs by the
// covariance, over each element, of the luminance and the point's kernel, which is second order
// in the element's size and of one sign where both peak together (the ceiling above a lit floor
// seen from the work plane below it): on an empty 4 × 3 × 3 m room with 0.5 m elements the work
// plane's total E is 1.8e-3 low against a converged reference, within 8.6e-4 with the slopes. Here
// each element's luminance slope in its plane is fitted by least squares to the means of the
// elements around it on the same face (never across an edge), cut back where a part of the element
// would get a negative luminance (beside a shadow edge: one share per element, set by the solved
// light of every channel, so that the gather stays linear in the luminance), and the elements near
// a point are gathered as their cells (the element halved each way) at the luminance of the line at
// each cell's centroid. A cell's mean of a linear luminance is its value at the centroid and the
// cells' values average to the element's mean, so the light the element sends is unchanged; only
// where it goes changes.
//
// Near: the element's bounding ball seen under (diameter / gap)² ≥ kNearRatio from the point
// (0.2: within about 1.6 m of a 0.5 m element); the share falls smoothly to none at a quarter of
// that (about 3.2 m), so that E stays smooth as a point moves. Farther elements change little
// across the point's kernel and keep their mean. The slopes are the default final gather of the
// dense transfer (MeshOptions::linearGather).
#include <Eigen/Dense>

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "engine/illuminance_engine.hpp"
#include "radiosity/element_ball.hpp"
#include "radiosity/surface_mesh.hpp"

namespace penumbra {

// Least-squares slope stencils: element i's slope is Σ_k weight[k] (L[neighbour[k]] − L[i]) over
// k in [start[i], start[i + 1]), in the element's plane (m⁻¹ per unit of L).
struct SlopeStencils {
  std::vector<std::size_t> start;
  std::vector<int> neighbour;
  std::vector<Vec3> weight;
};

// The neighbours of each element: the elements of the same solid's face whose centroids lie
// within 2.5 times the larger element's size (√area) of its own. An element with neighbours along
// one line only, or none, gets no stencil (a uniform luminance).
SlopeStencils slopeStencils(const SurfaceMesh& mesh);

// Element i's cells: polygons[k], k in [start[i], start[i + 1]), with offset[k] their centroid
// less the element's.
struct ElementCells {
  std::vector<ConvexPolygon> polygons;
  std::vector<std::size_t> start;
  std::vector<Vec3> offset;
};
ElementCells elementCells(const SurfaceMesh& mesh, double tolerance);

// Each element's share of its slope, in [0, 1]: the largest that leaves no cell below zero in any
// column of `reference` (N elements × C).
Eigen::VectorXd slopeShares(const SlopeStencils& stencils, const ElementCells& cells,
                            const Eigen::MatrixXd& reference);

// Per column c of `luminance` (N elements × C), each element's slope times its share in that
// column, share(i, c): slopes[c].row(i). Linear in `luminance` for given shares, so that the
// gather of a sum of luminances (the RGB channels and their photometric sum) is the sum of their
// gathers.
std::vector<Eigen::MatrixX3d> sharedSlopes(const SlopeStencils& stencils,
                                           const Eigen::MatrixXd& luminance,
                                           const Eigen::MatrixXd& share);

// What the slopes add to the gather of uniform elements, at each point: Σ over the elements
// near it of Σ over their cells of E_cell(point) · slope · offset, per column of `luminance`.
class SlopeGather {
 public:
  // The box room above: 8.3e-4 at 0.05, 8.6e-4 at 0.2, 8.8e-4 at 0.4, 9.7e-4 at 0.8; the
  // office's renders gather 1.6 times faster at 0.2 than at 0.05 (the near cells are the cost).
  static constexpr double kNearRatio = 0.2;

  // `scene`: the solids; `mesh`: the elements with their caster blocks, which the cells share.
  SlopeGather(compute::Device& device, const Scene& scene, const SurfaceMesh& mesh,
              const EngineOptions& engine, double tolerance);
  ~SlopeGather();

  // The shares (slopeShares) for the solved luminance `reference`.
  Eigen::VectorXd shares(const Eigen::MatrixXd& reference) const;
  // Per column c of `luminance`, with element i's slope scaled by share(i, c).
  Eigen::MatrixXd correction(std::span<const SamplePoint> points, const Eigen::MatrixXd& luminance,
                             const Eigen::MatrixXd& share);

 private:
  SlopeStencils stencils_;
  ElementCells cells_;
  std::vector<Ball> balls_;
  std::size_t firstCell_ = 0;  // cell k is source firstCell_ + k of engine_'s scene
  std::unique_ptr<IlluminanceEngine> engine_;
};

}  // namespace penumbra
