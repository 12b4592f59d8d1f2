#include "grid/grid_evaluation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "geometry/tolerance.hpp"
#include "grid/background_call.hpp"
#include "memory/page_prefault.hpp"

namespace penumbra {

namespace {

// A solid's vertex average c lies inside it, at least rho from every face plane. Every point x
// with n·x − d ≤ t for all faces (what faceContaining and containsStrictly accept at tolerance
// t) lies in c + (1 + t/rho)·(P − c): y = c + (x − c)/(1 + t/rho) is inside P, since for a face
// at distance a ≥ rho from c, n·y − d ≤ t·(1 − a/rho)/(1 + t/rho) ≤ 0. So the box of the solid's
// vertices, scaled about c by 1 + t/rho, holds every such point; it is grown by two more t for
// the rounding of the planes and of the tests. A solid too thin to bound this way (rho ≈ 0)
// is tested at every point.
constexpr double kMaxBoxScale = 1e3;

bool boundingBoxOf(const ConvexPolyhedron& shape, double tolerance, BoundingBox& box) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& v : shape.vertices()) c += v;
  c /= static_cast<double>(shape.vertices().size());
  double rho = std::numeric_limits<double>::infinity();
  for (const auto& face : shape.faces()) rho = std::min(rho, -face.plane.signedDistance(c));
  const double scale = 1.0 + tolerance / rho;
  if (!(rho > 0.0) || !(scale <= kMaxBoxScale)) return false;
  BoundingBox vertices;
  for (const Vec3& v : shape.vertices()) vertices.add(v);
  box.lo = c + scale * (vertices.lo - c);
  box.hi = c + scale * (vertices.hi - c);
  box = box.grown(2.0 * tolerance);
  return box.lo.allFinite() && box.hi.allFinite();
}

bool holds(const BoundingBox& box, const Vec3& p) {
  return (box.lo.array() <= p.array()).all() && (p.array() <= box.hi.array()).all();
}

// One solid of SolidLocator's, for one point.
struct SolidAtPoint {
  const ConvexPolyhedron& shape;
  const BoundingBox& box;  // empty: no box, tested everywhere
  int index;
  double tolerance;
};

// The solid's tests for the point, in the order classify takes the solids: whether the point lies
// on one of its faces (point.solid, kept for the face that looks most where the point looks) and
// whether the solid strictly contains it (`inside`, the first one that does).
void testSolidAtPoint(const SolidAtPoint& solid, SamplePoint& point, int& inside,
                      double& bestAlignment) {
  if (!solid.box.empty() && !holds(solid.box, point.position)) return;
  // A point can lie on faces of two solids (the floor under a desk's foot). It lies on the
  // one whose face looks where the point looks: the other one must still be able to shade it.
  const int face = solid.shape.faceContaining(point.position, point.normal, solid.tolerance);
  if (face >= 0) {
    const double alignment = solid.shape.faces()[face].plane.normal.dot(point.normal);
    if (alignment > bestAlignment) {
      bestAlignment = alignment;
      point.solid = solid.index;
    }
  }
  if (inside < 0 && solid.shape.containsStrictly(point.position, solid.tolerance))
    inside = solid.index;
}

}  // namespace

SolidLocator::SolidLocator(const Scene& scene) : scene_(&scene) {
  // Whether a grid point lies on a surface is a question about what a person typed (a sensor at
  // z = 0.75 on a desk top at 0.75): the input tolerance, relative to the scene's size, like the
  // loader's "on its wall" checks.
  tolerance_ = Tolerance::kRelativeInput * std::max(scene.size(), 1.0);
  const int count = static_cast<int>(scene.solids.size());
  boxes_.resize(count);
  std::vector<int> bounded;
  for (int s = 0; s < count; ++s) {
    const ConvexPolyhedron& shape = scene.solids[s].shape;
    if (shape.empty()) continue;  // an empty box: never a candidate, like the test it skips
    tested_.push_back(s);
    if (boundingBoxOf(shape, tolerance_, boxes_[s])) {
      bounds_.add(boxes_[s].lo);
      bounds_.add(boxes_[s].hi);
      bounded.push_back(s);
    } else {
      boxes_[s] = BoundingBox{};  // empty: tested at every point
      unbounded_.push_back(s);
    }
  }
  if (bounded.empty()) return;
  // About as many cells as solids, cubes as far as the scene's extent allows.
  const Vec3 extent = (bounds_.hi - bounds_.lo).cwiseMax(1e-3 * (bounds_.hi - bounds_.lo).norm());
  const double target = std::clamp<double>(static_cast<double>(bounded.size()), 1.0, 1 << 18);
  const double edge = std::cbrt(extent.prod() / target);
  for (int k = 0; k < 3; ++k) {
    cells_[k] = std::clamp(static_cast<int>(std::ceil(extent[k] / edge)), 1, 256);
  }
  const std::size_t cellCount = static_cast<std::size_t>(cells_[0]) * cells_[1] * cells_[2];
  cellSolids_.resize(cellCount);
  const auto cellOf = [&](const Vec3& p, int k) {
    const double f = (p[k] - bounds_.lo[k]) / (bounds_.hi[k] - bounds_.lo[k]) * cells_[k];
    return std::clamp(static_cast<int>(std::floor(f)), 0, cells_[k] - 1);
  };
  for (int s : bounded) {
    int lo[3], hi[3];
    std::size_t covered = 1;
    for (int k = 0; k < 3; ++k) {
      lo[k] = cellOf(boxes_[s].lo, k);
      hi[k] = cellOf(boxes_[s].hi, k);
      covered *= static_cast<std::size_t>(hi[k] - lo[k] + 1);
    }
    // A solid spanning much of the scene (a room's slab) would fill many cells: it is tested at
    // every point instead, which costs the same and keeps the cells small.
    if (covered > 64 && covered * 8 > cellCount) {
      unbounded_.insert(std::upper_bound(unbounded_.begin(), unbounded_.end(), s), s);
      continue;
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x)
          cellSolids_[(static_cast<std::size_t>(z) * cells_[1] + y) * cells_[0] + x].push_back(s);
  }
}

std::span<const int> SolidLocator::candidates(const Vec3& p) const {
  if (cellSolids_.empty() || !holds(bounds_, p)) return {};
  std::size_t index = 0;
  for (int k = 2; k >= 0; --k) {
    const double f = (p[k] - bounds_.lo[k]) / (bounds_.hi[k] - bounds_.lo[k]) * cells_[k];
    index = index * cells_[k] + std::clamp(static_cast<int>(std::floor(f)), 0, cells_[k] - 1);
  }
  return cellSolids_[index];
}

int SolidLocator::classifyAmong(SamplePoint& point, std::span<const int> solids) const {
  int inside = -1;
  double bestAlignment = -2.0;
  point.solid = -1;
  for (int s : solids)
    testSolidAtPoint(SolidAtPoint{scene_->solids[s].shape, boxes_[s], s, tolerance_}, point, inside,
                     bestAlignment);
  return inside;
}

void SolidLocator::classify(std::span<SamplePoint> points, std::span<int> inside) const {
  if (points.empty()) return;
  // A solid can answer for a point only if its box holds the point, so only if its box meets
  // the run's: the others are left out once, and the rest tested in scene order as one point's
  // classify tests them.
  BoundingBox run;
  for (const SamplePoint& p : points) run.add(p.position);
  std::vector<int> solids;
  for (int s : tested_)
    if (boxes_[s].empty() || boxes_[s].overlaps(run)) solids.push_back(s);
  for (std::size_t k = 0; k < points.size(); ++k) inside[k] = classifyAmong(points[k], solids);
}

int SolidLocator::classify(SamplePoint& point) const {
  const std::span<const int> near = candidates(point.position);
  int inside = -1;
  double bestAlignment = -2.0;
  point.solid = -1;
  const auto test = [&](int s) {
    testSolidAtPoint(SolidAtPoint{scene_->solids[s].shape, boxes_[s], s, tolerance_}, point, inside,
                     bestAlignment);
  };
  // Both lists ascend: merged, the solids are tested in scene order, as a plain loop would.
  auto a = near.begin();
  auto b = unbounded_.begin();
  while (a != near.end() || b != unbounded_.end()) {
    if (b == unbounded_.end() || (a != near.end() && *a < *b)) {
      test(*a++);
    } else {
      test(*b++);
    }
  }
  return inside;
}

GridSamples gridSamples(const SolidLocator& solids, const CalculationGrid& grid, std::size_t first,
                        std::size_t count) {
  const std::size_t end = first + std::min(count, grid.size() - std::min(first, grid.size()));
  GridSamples samples;
  samples.points.reserve(end - std::min(first, end));
  samples.inside.reserve(end - std::min(first, end));
  for (std::size_t i = first; i < end; ++i) {
    SamplePoint point{grid.position(i), grid.normal(i), -1};
    samples.inside.push_back(solids.classify(point));
    samples.points.push_back(point);
  }
  return samples;
}

std::vector<SamplePoint> GridSamples::outsideSolids() const {
  std::vector<SamplePoint> outside;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (inside[i] < 0) outside.push_back(points[i]);
  return outside;
}

GridSamples gridSamples(const Scene& scene, const CalculationGrid& grid) {
  return gridSamples(SolidLocator(scene), grid);
}

bool facesUp(const CalculationGrid& grid) {
  // Unit normals within 1e-6 rad of +z: a plane a user means to be horizontal, built from
  // rounded input.
  const auto up = [&](std::size_t i) { return grid.normal(i).z() >= 1.0 - 5e-13; };
  if (grid.size() == 0) return false;
  if (grid.kind != GridKind::Points) return up(0);
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (!up(i)) return false;
  return true;
}

GridRun streamGrid(const Scene& scene, const CalculationGrid& grid,
                   const IlluminanceEstimator& estimate, std::size_t batchSize,
                   const GridBatchSink& sink, const ProgressCallback& progress) {
  const auto start = std::chrono::steady_clock::now();
  GridRun run;
  run.name = grid.name;
  const SolidLocator solids(scene);
  const std::size_t n = grid.size();
  batchSize = std::max<std::size_t>(batchSize, 1);
  GridMetricsSum sums;

  // Points are classified a block at a time, ahead of the chunks that take them, and in
  // parallel: a point's answer depends on that point alone. 4096 points (230 KB) stay in cache
  // until the chunk takes them, and are four tasks of 1024 for the parallel loop.
  constexpr std::size_t block = 4096;
  std::vector<SamplePoint> aheadPoints;
  std::vector<int> aheadInside;
  std::size_t aheadFirst = 0;
  const auto classified = [&](std::size_t i) {
    if (i >= aheadFirst + aheadPoints.size()) {
      aheadFirst = i;
      const std::size_t count = std::min(block, n - i);
      aheadPoints.resize(count);
      aheadInside.resize(count);
      tbb::parallel_for(
          tbb::blocked_range<std::size_t>(0, count, 1024),
          [&](const tbb::blocked_range<std::size_t>& range) {
            for (std::size_t k = range.begin(); k != range.end(); ++k)
              aheadPoints[k] = SamplePoint{grid.position(i + k), grid.normal(i + k), -1};
            solids.classify(std::span(aheadPoints).subspan(range.begin(), range.size()),
                            std::span(aheadInside).subspan(range.begin(), range.size()));
          });
    }
    return i - aheadFirst;
  };

  // One chunk of consecutive grid points: up to batchSize of them outside solids (the
  // estimator's batch) and the inside points among them.
  struct Chunk {
    std::size_t first = 0;
    std::vector<SamplePoint> outside;
    std::vector<std::size_t> outsideAt;  // offsets in the chunk
    std::vector<int> inside, onSolid;
  };
  std::size_t next = 0;
  const auto gather = [&](Chunk& chunk) {
    chunk.first = next;
    chunk.outside.clear();
    chunk.outsideAt.clear();
    chunk.inside.clear();
    chunk.onSolid.clear();
    chunk.outside.reserve(batchSize);
    chunk.outsideAt.reserve(batchSize);
    chunk.inside.reserve(batchSize);
    chunk.onSolid.reserve(batchSize);
    // Full: a batch for the estimator, or a run of inside points with nothing waiting for it,
    // which goes on at once.
    const auto full = [&] {
      return chunk.outside.size() >= batchSize ||
             (chunk.outside.empty() && chunk.inside.size() >= batchSize);
    };
    while (next < n && !full()) {
      // The rest of the classified block, point by point.
      const std::size_t first = classified(next);
      const std::size_t end = first + std::min(aheadPoints.size() - first, n - next);
      std::size_t k = first;
      while (k < end && !full()) {
        // A run of points outside solids, as far as the batch has room, is taken whole; a point
        // inside a solid alone.
        std::size_t stop = k + 1;
        if (aheadInside[k] < 0) {
          const std::size_t room = batchSize - chunk.outside.size();
          stop = k;
          while (stop < end && stop - k < room && aheadInside[stop] < 0) ++stop;
          const std::size_t at = chunk.inside.size();
          for (std::size_t j = k; j < stop; ++j) chunk.outsideAt.push_back(at + (j - k));
          chunk.outside.insert(chunk.outside.end(), aheadPoints.begin() + k,
                               aheadPoints.begin() + stop);
        }
        chunk.inside.insert(chunk.inside.end(), aheadInside.begin() + k,
                            aheadInside.begin() + stop);
        for (std::size_t j = k; j < stop; ++j) chunk.onSolid.push_back(aheadPoints[j].solid);
        k = stop;
      }
      next += k - first;
    }
  };

  std::vector<double> e, direct, sun, sunReflected, skyComponent, externalComponent;
  double skyComponentSum = 0.0, externalComponentSum = 0.0;  // lx, points not inside solids
  GridMetricsSum directSums;
  SunMetricsSum sunSums;
  std::vector<double> daylightTotal, daylightDirect;  // lx, points not inside solids (a sky)
  // Whether the estimator gives the direct part too, known from its first answer; the points
  // before it are inside solids (E = 0, direct part 0).
  bool answered = false, split = false, components = false;
  // The chunk's values into the metrics, then to the sink.
  const auto finish = [&](const Chunk& chunk, const PointIlluminance& values) {
    const std::vector<int>& inside = chunk.inside;
    const std::vector<std::size_t>& outsideAt = chunk.outsideAt;
    e.assign(inside.size(), 0.0);
    direct.assign(split ? inside.size() : 0, 0.0);
    sun.assign(scene.sun ? inside.size() : 0, 0.0);
    sunReflected.assign(scene.sun && split ? inside.size() : 0, 0.0);
    skyComponent.assign(components ? inside.size() : 0, 0.0);
    externalComponent.assign(components ? inside.size() : 0, 0.0);
    if (!chunk.outside.empty()) {
      if (values.total.size() != chunk.outside.size() ||
          (!values.direct.empty() && values.direct.size() != chunk.outside.size()) ||
          (!values.sun.empty() && values.sun.size() != chunk.outside.size()) ||
          (!values.sunReflected.empty() && values.sunReflected.size() != chunk.outside.size()) ||
          (!values.skyComponent.empty() && values.skyComponent.size() != chunk.outside.size()) ||
          values.externalComponent.size() != values.skyComponent.size() ||
          (answered && split == values.direct.empty()) ||
          (answered && components == values.skyComponent.empty())) {
        throw std::logic_error("estimator returned the wrong number of values");
      }
      if (!answered) {
        answered = true;
        split = !values.direct.empty();
        components = !values.skyComponent.empty();
        direct.assign(split ? inside.size() : 0, 0.0);
        sunReflected.assign(scene.sun && split ? inside.size() : 0, 0.0);
        skyComponent.assign(components ? inside.size() : 0, 0.0);
        externalComponent.assign(components ? inside.size() : 0, 0.0);
      }
      for (std::size_t k = 0; k < values.total.size(); ++k) e[outsideAt[k]] = values.total[k];
      for (std::size_t k = 0; k < values.direct.size(); ++k)
        direct[outsideAt[k]] = values.direct[k];
      if (!sun.empty())
        for (std::size_t k = 0; k < values.sun.size(); ++k) sun[outsideAt[k]] = values.sun[k];
      if (!sunReflected.empty())
        for (std::size_t k = 0; k < values.sunReflected.size(); ++k)
          sunReflected[outsideAt[k]] = values.sunReflected[k];
      for (std::size_t k = 0; k < values.skyComponent.size(); ++k) {
        skyComponent[outsideAt[k]] = values.skyComponent[k];
        externalComponent[outsideAt[k]] = values.externalComponent[k];
        skyComponentSum += values.skyComponent[k];
        externalComponentSum += values.externalComponent[k];
      }
    }
    for (std::size_t k = 0; k < e.size(); ++k) sums.add(e[k], inside[k] >= 0);
    // The daylight factor leaves the sun out, direct and reflected.
    if (scene.sky)
      for (std::size_t k = 0; k < e.size(); ++k) {
        if (inside[k] >= 0) continue;
        const double sunPart = k < sun.size() ? sun[k] : 0.0;
        const double sunReflectedPart = k < sunReflected.size() ? sunReflected[k] : 0.0;
        daylightTotal.push_back(e[k] - sunPart - sunReflectedPart);
        daylightDirect.push_back((k < direct.size() ? direct[k] : e[k]) - sunPart);
      }
    for (std::size_t k = 0; k < sun.size(); ++k) sunSums.add(sun[k], inside[k] >= 0);
    for (std::size_t k = 0; k < e.size(); ++k)
      directSums.add(k < direct.size() ? direct[k] : e[k], inside[k] >= 0);
    if (sink)
      sink(GridBatch{chunk.first, e, direct, sun, sunReflected, skyComponent, externalComponent,
                     inside, chunk.onSolid});
    if (progress) progress(chunk.first + inside.size(), n);
  };

  // A pipeline of two chunks: while the estimator computes one chunk on a thread of its own,
  // this thread classifies and gathers the next. The estimator sees the same batches in the same
  // order, one call at a time, and the sink the same chunks in grid order, on this thread.
  if (progress) progress(0, n);
  BackgroundCall<PointIlluminance> estimator;
  if (n > batchSize) {
    // Batches after the first reuse the first's memory: both threads map theirs at once
    // (memory/page_prefault.hpp), about 512 bytes a point of a batch each.
    const std::size_t bytes = batchSize * 512;
    estimator.start([bytes] {
      prefaultHeap(bytes);
      return PointIlluminance();
    });
    prefaultHeap(bytes);
    estimator.result();
  }
  Chunk current, following;
  gather(current);
  while (!current.inside.empty()) {
    const bool estimated = !current.outside.empty();
    if (estimated)
      estimator.start([&estimate, &current] {
        return estimate(std::span<const SamplePoint>(current.outside));
      });
    gather(following);
    finish(current, estimated ? estimator.result() : PointIlluminance());
    std::swap(current, following);
  }
  run.metrics = sums.metrics(grid.spacing);
  if (split) run.directMetrics = directSums.metrics(grid.spacing);
  const std::size_t daylightTotalCount = daylightTotal.size();
  if (scene.sky)
    run.daylight =
        daylightMetrics(std::move(daylightTotal), daylightDirect, scene.sky->horizontalIlluminance,
                        scene.site && facesUp(grid) ? scene.site->medianDiffuseIlluminance
                                                    : std::optional<double>());
  if (run.daylight) {
    run.daylight->horizontal = facesUp(grid);
    if (components) {
      // Means in %: the sums over the points counted, in units of E_h / 100.
      const double perPoint = daylightTotalCount > 0 ? 100.0 / scene.sky->horizontalIlluminance /
                                                           static_cast<double>(daylightTotalCount)
                                                     : std::numeric_limits<double>::quiet_NaN();
      run.daylight->components = daylightComponents(*run.daylight, perPoint * skyComponentSum,
                                                    perPoint * externalComponentSum);
    }
  }
  if (scene.sun) run.sun = sunSums.metrics();
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

GridEvaluation evaluateGrid(const Scene& scene, const CalculationGrid& grid,
                            const IlluminanceEstimator& estimate, std::size_t batchSize,
                            const ProgressCallback& progress) {
  GridEvaluation evaluation;
  evaluation.samples.points.reserve(grid.size());
  evaluation.samples.inside.reserve(grid.size());
  evaluation.illuminance.reserve(grid.size());
  const GridBatchSink keep = [&](const GridBatch& batch) {
    for (std::size_t k = 0; k < batch.illuminance.size(); ++k) {
      const std::size_t i = batch.first + k;
      evaluation.samples.points.push_back(
          SamplePoint{grid.position(i), grid.normal(i), batch.onSolid[k]});
      evaluation.samples.inside.push_back(batch.inside[k]);
      evaluation.illuminance.push_back(batch.illuminance[k]);
      // A batch before the estimator's first answer holds inside points only: direct = total = 0.
      evaluation.direct.push_back(batch.direct.empty() ? batch.illuminance[k] : batch.direct[k]);
      if (!batch.sun.empty()) evaluation.sun.push_back(batch.sun[k]);
      if (!batch.sunReflected.empty()) evaluation.sunReflected.push_back(batch.sunReflected[k]);
      if (!batch.skyComponent.empty()) {
        evaluation.skyComponent.push_back(batch.skyComponent[k]);
        evaluation.externalComponent.push_back(batch.externalComponent[k]);
      }
    }
  };
  const GridRun run = streamGrid(scene, grid, estimate, batchSize, keep, progress);
  evaluation.name = run.name;
  evaluation.metrics = run.metrics;
  evaluation.daylight = run.daylight;
  evaluation.sunMetrics = run.sun;
  if (!run.directMetrics) evaluation.direct.clear();
  evaluation.seconds = run.seconds;
  return evaluation;
}

}  // namespace penumbra
