#include "radiosity/luminance_slopes.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include "geometry/primitives.hpp"
#include "kernels/shared_types.h"
#include "radiosity/element_transfer.hpp"

namespace penumbra {

namespace {

// Values per work-item of PN_LANES points, at most this many faces a launch (as the transfer's
// launches: about 2^22 values).
constexpr std::size_t kFacesPerLaunch = (std::size_t{1} << 22) / PN_LANES;

// The share of an element's slope that a point takes: 1 where the element's ball is seen under
// (diameter / gap)² ≥ kNearRatio, 0 below a quarter of that, and a smooth step between, so that
// the gathered E stays smooth as a point moves away from an element.
double nearWeight(const Ball& ball, const Vec3& point) {
  const double gap = (point - ball.centre).norm() - ball.radius;
  const double diameter = 2.0 * ball.radius;
  if (gap <= 0.0) return 1.0;
  const double ratio = diameter * diameter / (gap * gap);
  const double t = std::clamp((ratio / SlopeGather::kNearRatio - 0.25) / 0.75, 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

SlopeStencils slopeStencils(const SurfaceMesh& mesh) {
  const std::size_t n = mesh.elements.size();
  std::map<std::pair<int, int>, std::vector<std::size_t>> byFace;
  for (std::size_t i = 0; i < n; ++i)
    byFace[{mesh.elements[i].solid, mesh.elements[i].face}].push_back(i);
  std::vector<Vec3> centroid(n);
  for (std::size_t i = 0; i < n; ++i) centroid[i] = mesh.elements[i].polygon.centroid();

  std::vector<std::vector<std::pair<int, Vec3>>> rows(n);
  for (const auto& face : byFace) {
    const std::vector<std::size_t>& members = face.second;  // (clang 14 cannot capture a binding)
    tbb::parallel_for(std::size_t{0}, members.size(), [&](std::size_t a) {
      const std::size_t i = members[a];
      const SurfaceElement& e = mesh.elements[i];
      const auto [u, v] = frameAround(e.polygon.normal(), Vec3::UnitX());
      Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
      std::vector<std::pair<int, Eigen::Vector2d>> near;
      for (std::size_t j : members) {
        if (j == i) continue;
        const Vec3 d = centroid[j] - centroid[i];
        const double reach = 2.5 * std::sqrt(std::max(e.area, mesh.elements[j].area));
        if (d.squaredNorm() > reach * reach) continue;
        const Eigen::Vector2d d2(d.dot(u), d.dot(v));
        const double w = 1.0 / d2.squaredNorm();  // nearer neighbours count more
        normal += w * d2 * d2.transpose();
        near.emplace_back(static_cast<int>(j), w * d2);
      }
      // Neighbours along one line only leave the slope across it unknown: none at all then.
      if (near.size() < 2 || normal.determinant() <= 1e-6 * normal.squaredNorm()) return;
      const Eigen::Matrix2d inverse = normal.inverse();
      for (const auto& [j, wd] : near) {
        const Eigen::Vector2d g = inverse * wd;
        rows[i].emplace_back(j, g.x() * u + g.y() * v);
      }
    });
  }
  SlopeStencils stencils;
  stencils.start.reserve(n + 1);
  stencils.start.push_back(0);
  for (const auto& row : rows) {
    for (const auto& [j, w] : row) {
      stencils.neighbour.push_back(j);
      stencils.weight.push_back(w);
    }
    stencils.start.push_back(stencils.neighbour.size());
  }
  return stencils;
}

ElementCells elementCells(const SurfaceMesh& mesh, double tolerance) {
  ElementCells cells;
  cells.start.push_back(0);
  for (const SurfaceElement& element : mesh.elements) {
    const Vec3 centre = element.polygon.centroid();
    for (ConvexPolygon& cell : halved(element.polygon, tolerance)) {
      cells.offset.push_back(cell.centroid() - centre);
      cells.polygons.push_back(std::move(cell));
    }
    cells.start.push_back(cells.polygons.size());
  }
  return cells;
}

namespace {

// Element i's least-squares slope of column c (m⁻¹ per unit of L).
Vec3 fittedSlope(const SlopeStencils& stencils, const Eigen::MatrixXd& luminance, std::size_t i,
                 Eigen::Index c) {
  const double own = luminance(static_cast<Eigen::Index>(i), c);
  Vec3 g = Vec3::Zero();
  for (std::size_t k = stencils.start[i]; k < stencils.start[i + 1]; ++k)
    g += stencils.weight[k] * (luminance(stencils.neighbour[k], c) - own);
  return g;
}

}  // namespace

Eigen::VectorXd slopeShares(const SlopeStencils& stencils, const ElementCells& cells,
                            const Eigen::MatrixXd& reference) {
  const Eigen::Index n = reference.rows();
  Eigen::VectorXd share = Eigen::VectorXd::Ones(n);
  for (Eigen::Index c = 0; c < reference.cols(); ++c)
    for (Eigen::Index i = 0; i < n; ++i) {
      const auto e = static_cast<std::size_t>(i);
      const Vec3 g = fittedSlope(stencils, reference, e, c);
      for (std::size_t k = cells.start[e]; k < cells.start[e + 1]; ++k) {
        const double rise = g.dot(cells.offset[k]);
        if (rise < 0.0) share[i] = std::min(share[i], std::max(0.0, -reference(i, c) / rise));
      }
    }
  return share;
}

std::vector<Eigen::MatrixX3d> sharedSlopes(const SlopeStencils& stencils,
                                           const Eigen::MatrixXd& luminance,
                                           const Eigen::MatrixXd& share) {
  const Eigen::Index n = luminance.rows();
  std::vector<Eigen::MatrixX3d> slopes(static_cast<std::size_t>(luminance.cols()),
                                       Eigen::MatrixX3d::Zero(n, 3));
  for (Eigen::Index c = 0; c < luminance.cols(); ++c)
    for (Eigen::Index i = 0; i < n; ++i)
      slopes[static_cast<std::size_t>(c)].row(i) =
          (share(i, c) * fittedSlope(stencils, luminance, static_cast<std::size_t>(i), c))
              .transpose();
  return slopes;
}

SlopeGather::SlopeGather(compute::Device& device, const Scene& scene, const SurfaceMesh& mesh,
                         const EngineOptions& engine, double tolerance)
    : stencils_(slopeStencils(mesh)), cells_(elementCells(mesh, tolerance)) {
  // The cells as unit sources sharing their element's caster block, as the elements do.
  SurfaceMesh cellMesh;
  cellMesh.casterBlocks = mesh.casterBlocks;
  for (std::size_t i = 0; i < mesh.elements.size(); ++i) {
    const SurfaceElement& element = mesh.elements[i];
    balls_.push_back(ballOf(element.polygon));
    for (std::size_t k = cells_.start[i]; k < cells_.start[i + 1]; ++k)
      cellMesh.elements.push_back({cells_.polygons[k], element.solid, element.face,
                                   element.reflectance, cells_.polygons[k].area(),
                                   element.casterBlock});
  }
  firstCell_ = cellMesh.casterBlocks.size();
  engine_ = std::make_unique<IlluminanceEngine>(device, elementSceneSharingCasters(scene, cellMesh),
                                                engine);
}

SlopeGather::~SlopeGather() = default;

Eigen::VectorXd SlopeGather::shares(const Eigen::MatrixXd& reference) const {
  return slopeShares(stencils_, cells_, reference);
}

Eigen::MatrixXd SlopeGather::correction(std::span<const SamplePoint> points,
                                        const Eigen::MatrixXd& luminance,
                                        const Eigen::MatrixXd& share) {
  const Eigen::Index columns = luminance.cols();
  Eigen::MatrixXd e = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(points.size()), columns);
  const std::size_t n = balls_.size();
  if (n == 0 || points.empty()) return e;
  const std::vector<Eigen::MatrixX3d> slopes = sharedSlopes(stencils_, luminance, share);

  // Each work-item's points (PN_LANES in a row, the last repeated) and the elements near any of
  // them, with each lane's weight of their slopes (nearWeight).
  using LaneWeights = std::array<double, PN_LANES>;
  const std::size_t items = (points.size() + PN_LANES - 1) / PN_LANES;
  std::vector<std::vector<int>> near(items);
  std::vector<std::vector<LaneWeights>> weights(items);
  const auto pointOf = [&](std::size_t item, std::size_t lane) {
    return std::min(item * PN_LANES + lane, points.size() - 1);
  };
  tbb::parallel_for(std::size_t{0}, items, [&](std::size_t w) {
    for (std::size_t i = 0; i < n; ++i) {
      if (stencils_.start[i + 1] == stencils_.start[i]) continue;  // no slope: its mean alone
      LaneWeights lanes{};
      bool any = false;
      for (std::size_t lane = 0; lane < PN_LANES && w * PN_LANES + lane < points.size(); ++lane) {
        lanes[lane] = nearWeight(balls_[i], points[pointOf(w, lane)].position);
        any = any || lanes[lane] > 0.0;
      }
      if (!any) continue;
      near[w].push_back(static_cast<int>(i));
      weights[w].push_back(lanes);
    }
  });

  // Jobs: a work-item and a range of its near elements' cells. A job whose occluders overflow
  // the kernel's room is split in two and asked again.
  struct Job {
    std::size_t item;
    std::vector<int> cells;  // cell indices
    std::vector<LaneWeights> weight;
  };
  std::vector<Job> jobs;
  for (std::size_t w = 0; w < items; ++w) {
    if (near[w].empty()) continue;
    Job job{w, {}, {}};
    for (std::size_t k = 0; k < near[w].size(); ++k) {
      const auto i = static_cast<std::size_t>(near[w][k]);
      for (std::size_t c = cells_.start[i]; c < cells_.start[i + 1]; ++c) {
        job.cells.push_back(static_cast<int>(c));
        job.weight.push_back(weights[w][k]);
      }
    }
    jobs.push_back(std::move(job));
  }
  // Each cell's rise above its element's mean, per column: the same for every point.
  Eigen::MatrixXd rise(static_cast<Eigen::Index>(cells_.polygons.size()), columns);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = cells_.start[i]; c < cells_.start[i + 1]; ++c)
      for (Eigen::Index k = 0; k < columns; ++k)
        rise(static_cast<Eigen::Index>(c), k) = slopes[static_cast<std::size_t>(k)]
                                                    .row(static_cast<Eigen::Index>(i))
                                                    .dot(cells_.offset[c].transpose());

  while (!jobs.empty()) {
    std::vector<Job> again;
    for (std::size_t first = 0; first < jobs.size();) {
      std::size_t last = first, faces = 0;
      while (last < jobs.size() &&
             (last == first || faces + jobs[last].cells.size() <= kFacesPerLaunch))
        faces += jobs[last++].cells.size();
      std::vector<SamplePoint> lanes;
      std::vector<std::int32_t> start = {0}, sources;
      for (std::size_t j = first; j < last; ++j) {
        for (std::size_t lane = 0; lane < PN_LANES; ++lane)
          lanes.push_back(points[pointOf(jobs[j].item, lane)]);
        for (int c : jobs[j].cells) sources.push_back(static_cast<std::int32_t>(firstCell_) + c);
        start.push_back(static_cast<std::int32_t>(sources.size()));
      }
      std::vector<int> overflow;
      const std::vector<float> values =
          engine_->linkedIlluminance(lanes, start, sources, &overflow);
      for (std::size_t j = first; j < last; ++j) {
        Job& job = jobs[j];
        const std::size_t w = j - first;
        if (overflow[w] != 0) {
          if (job.cells.size() < 2)
            throw std::runtime_error("too many occluders before one element's cell");
          const std::size_t half = job.cells.size() / 2;
          Job rest{job.item, std::vector<int>(job.cells.begin() + half, job.cells.end()),
                   std::vector<LaneWeights>(job.weight.begin() + half, job.weight.end())};
          job.cells.resize(half), job.weight.resize(half);
          again.push_back(std::move(job));
          again.push_back(std::move(rest));
          continue;
        }
        for (std::size_t k = 0; k < job.cells.size(); ++k) {
          const auto cell = static_cast<Eigen::Index>(job.cells[k]);
          for (std::size_t lane = 0; lane < PN_LANES; ++lane) {
            const double weight = job.weight[k][lane];
            if (weight == 0.0) continue;
            const double unit =
                weight * values[(static_cast<std::size_t>(start[w]) + k) * PN_LANES + lane];
            const auto p = static_cast<Eigen::Index>(job.item * PN_LANES + lane);
            e.row(p) += unit * rise.row(cell);
          }
        }
      }
      first = last;
    }
    jobs = std::move(again);
  }
  return e;
}

}  // namespace penumbra
