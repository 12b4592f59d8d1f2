#include "radiosity/element_transfer.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/tolerance.hpp"
#include "kernels/shared_types.h"
#include "memory/page_prefault.hpp"
#include "radiosity/element_ball.hpp"
#include "radiosity/element_quadrature.hpp"

namespace penumbra {

namespace {

// The n × n transfer, zero, its pages mapped at once (memory/page_prefault.hpp): 195 MB on the
// open office, 48 000 pages that would otherwise fault in one by one as it is zeroed.
Eigen::MatrixXd zeroTransfer(std::size_t n) {
  const auto size = static_cast<Eigen::Index>(n);
  Eigen::MatrixXd t(size, size);
  populatePages(t.data(), static_cast<std::size_t>(t.size()) * sizeof(double));
  t.setZero();
  return t;
}

// The scene's solids with the blocks (if `blocks`) and then the elements as sources.
Scene elementSources(const Scene& scene, const SurfaceMesh& mesh, bool blocks) {
  Scene elements = solidsOf(scene);
  const std::size_t first = blocks ? mesh.casterBlocks.size() : 0;
  elements.sources.reserve(first + mesh.elements.size());
  for (std::size_t b = 0; b < first; ++b) {
    Source source;
    source.name = "element-block-" + std::to_string(b);
    source.faces = {mesh.casterBlocks[b]};
    source.castersOnly = true;
    elements.sources.push_back(std::move(source));
  }
  for (std::size_t i = 0; i < mesh.elements.size(); ++i) {
    Source source;
    source.name = "element-" + std::to_string(i);
    source.faces = {mesh.elements[i].polygon};
    source.luminance = 1.0;
    if (blocks) source.castersOf = mesh.elements[i].casterBlock;
    elements.sources.push_back(std::move(source));
  }
  return elements;
}

// About 2^22 point·element values (16 MB of float) per launch.
constexpr std::size_t kTransferBatchValues = std::size_t{1} << 22;

// Which pairs a transfer by batches computed: t(i, j) at i's points where j >= firstSender[i],
// the first receiver of i's batch. Every pair has at least one direction computed (for j before
// i's batch, i is at or after the first receiver of j's).
struct ComputedPairs {
  std::vector<std::size_t> firstSender;
  bool computed(std::size_t i, std::size_t j) const { return j >= firstSender[i]; }
};

// t(i, j) for every receiver i and sender j (the engine's source firstElement + j): receiver i
// takes points[start[i] … start[i + 1]), and `average(values, i, count)` reduces sender j's
// values at its count points to t(i, j). Whole receivers per launch, about kTransferBatchValues
// values each, the launches pipelined (illuminanceBySourceBatches). With `half`, a batch
// computes only the senders from its own first receiver on, about half of the pairs, and the
// rest of t is left as it was.
template <class Average>
ComputedPairs transferByBatches(IlluminanceEngine& engine, std::span<const SamplePoint> points,
                                std::span<const std::size_t> start, std::size_t firstElement,
                                Eigen::MatrixXd& t, const Average& average, bool half = false) {
  const std::size_t n = start.size() - 1;
  ComputedPairs pairs{std::vector<std::size_t>(n, 0)};
  std::vector<std::size_t> firstOf;  // batch → its first receiver; one more entry, n
  for (std::size_t first = 0; first < n;) {
    firstOf.push_back(first);
    std::size_t last = first + 1;
    while (last < n && (start[last + 1] - start[first]) * n <= kTransferBatchValues) ++last;
    first = last;
  }
  firstOf.push_back(n);
  std::vector<std::span<const SamplePoint>> batches;
  for (std::size_t b = 0; b + 1 < firstOf.size(); ++b) {
    batches.push_back(points.subspan(start[firstOf[b]], start[firstOf[b + 1]] - start[firstOf[b]]));
    if (half)
      for (std::size_t i = firstOf[b]; i < firstOf[b + 1]; ++i) pairs.firstSender[i] = firstOf[b];
  }
  const auto computes = [&](std::size_t b, std::size_t source) {
    return source < firstElement || source - firstElement >= firstOf[b];
  };
  engine.illuminanceBySourceBatches(
      batches,
      [&](std::size_t b, const std::vector<float>& e, std::size_t stride) {
        const std::size_t first = firstOf[b], last = firstOf[b + 1], begin = start[first];
        for (std::size_t j = half ? first : 0; j < n; ++j) {
          const float* row = e.data() + (firstElement + j) * stride;
          for (std::size_t i = first; i < last; ++i)
            t(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
                average(row + (start[i] - begin), i, start[i + 1] - start[i]);
        }
      },
      half ? IlluminanceEngine::BatchSources(computes) : IlluminanceEngine::BatchSources());
  return pairs;
}

}  // namespace

Scene elementScene(const Scene& scene, const SurfaceMesh& mesh) {
  return elementSources(scene, mesh, false);
}

Scene elementSceneSharingCasters(const Scene& scene, const SurfaceMesh& mesh) {
  return elementSources(scene, mesh, true);
}

Eigen::MatrixXd elementTransfer(IlluminanceEngine& engine, const SurfaceMesh& mesh,
                                std::size_t firstElement) {
  const auto n = static_cast<Eigen::Index>(mesh.elements.size());
  Eigen::MatrixXd t = zeroTransfer(static_cast<std::size_t>(n));
  if (n == 0) return t;
  transferByBatches(engine, mesh.nodes, mesh.nodeStart, firstElement, t,
                    [&](const float* values, std::size_t i, std::size_t count) {
                      double sum = 0.0;
                      for (std::size_t k = 0; k < count; ++k)
                        sum += mesh.weights[mesh.nodeStart[i] + k] * values[k];
                      return sum;
                    });
  return t;
}

namespace {

// Each receiver's senders by how its row takes them (FarFieldRule), in increasing order: `near`,
// those it can exchange light with that are not far; `ownPoints`, the far ones not computed at
// its far points (`computed`) that are not far enough for reciprocity.
struct SenderLists {
  std::vector<std::vector<int>> near, ownPoints;
};

SenderLists senderLists(const SurfaceMesh& mesh, const FarFieldRule& rule,
                        const ComputedPairs& computed) {
  const std::size_t n = mesh.elements.size();
  std::vector<Ball> balls(n);
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (std::size_t i = 0; i < n; ++i) {
    balls[i] = ballOf(mesh.elements[i].polygon);
    lo = lo.cwiseMin(balls[i].centre - Vec3::Constant(balls[i].radius));
    hi = hi.cwiseMax(balls[i].centre + Vec3::Constant(balls[i].radius));
  }
  const double tolerance = Tolerance::forSceneSize((hi - lo).norm()).length;
  SenderLists lists{std::vector<std::vector<int>>(n), std::vector<std::vector<int>>(n)};
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    const double diameter = 2.0 * balls[i].radius;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i) continue;
      const double gap = ballGap(balls[i], balls[j]);
      const bool far = gap > 0.0 && (diameter / gap) * (diameter / gap) <= rule.farRatio;
      const double larger = 2.0 * std::max(balls[i].radius, balls[j].radius);
      const bool reciprocal = far && (larger / gap) * (larger / gap) <= rule.reciprocalRatio;
      if (far && (reciprocal || computed.computed(i, j))) continue;
      if (canExchange(mesh.elements[i].polygon, mesh.elements[j].polygon, tolerance))
        (far ? lists.ownPoints : lists.near)[i].push_back(static_cast<int>(j));
    }
  });
  return lists;
}

// The points where a receiver takes its far senders: on a parallelogram the 2 × 2
// Gauss-Legendre points (exact for a light that is cubic along each side), on any other polygon
// its centroid; equal weights.
std::vector<SamplePoint> farPoints(const SurfaceElement& element) {
  const ConvexPolygon& polygon = element.polygon;
  const Vec3 normal = polygon.normal();
  if (!isParallelogram(polygon)) return {SamplePoint{polygon.centroid(), normal, element.solid}};
  const GaussRule gauss = gaussLegendre01(2);
  const std::vector<Vec3>& v = polygon.vertices();
  std::vector<SamplePoint> points;
  for (double a : gauss.nodes)
    for (double b : gauss.nodes)
      points.push_back(
          SamplePoint{v[0] + a * (v[1] - v[0]) + b * (v[3] - v[0]), normal, element.solid});
  return points;
}

// Points at which each receiver takes its senders, with weights that average over them:
// receiver i has points[start[i] … start[i + 1]).
struct ReceiverPoints {
  std::span<const SamplePoint> points;
  std::span<const double> weights;
  std::span<const std::size_t> start;
};

ReceiverPoints nodesOf(const SurfaceMesh& mesh) {
  return {mesh.nodes, mesh.weights, mesh.nodeStart};
}

// Every element's far points (farPoints) at equal weights.
struct FarPoints {
  std::vector<SamplePoint> points;
  std::vector<double> weights;
  std::vector<std::size_t> start = {0};
  explicit FarPoints(const SurfaceMesh& mesh) {
    for (const SurfaceElement& element : mesh.elements) {
      const std::vector<SamplePoint> own = farPoints(element);
      points.insert(points.end(), own.begin(), own.end());
      weights.insert(weights.end(), own.size(), 1.0 / static_cast<double>(own.size()));
      start.push_back(points.size());
    }
  }
  ReceiverPoints view() const { return {points, weights, start}; }
};

// t(i, j) = the mean of E from element j over element i's far points (farPoints), lx per
// cd/m², every pair; with `half`, each pair computed one way (transferByBatches) and the other
// way by reciprocity: area(i)·t(i, j) = area(j)·t(j, i) holds for the exact transfer.
ComputedPairs farPointTransfer(IlluminanceEngine& engine, const SurfaceMesh& mesh,
                               const FarPoints& far, std::size_t firstElement, bool half,
                               Eigen::MatrixXd& t) {
  const ComputedPairs pairs = transferByBatches(
      engine, far.points, far.start, firstElement, t,
      [](const float* values, std::size_t, std::size_t count) {
        double sum = 0.0;
        for (std::size_t k = 0; k < count; ++k) sum += values[k];
        return sum / static_cast<double>(count);
      },
      half);
  if (half)
    tbb::parallel_for(std::size_t{0}, mesh.elements.size(), [&](std::size_t i) {
      const auto row = static_cast<Eigen::Index>(i);
      for (std::size_t j = 0; j < pairs.firstSender[i]; ++j) {
        const auto column = static_cast<Eigen::Index>(j);
        t(row, column) = mesh.elements[j].area / mesh.elements[i].area * t(column, row);
      }
    });
  return pairs;
}

// The average over receiver i's points of E from each of senders[i] (the receivers in
// `receivers`), by the kernel's linked launch: the same floats as illuminanceBySource, so the
// same sums as elementTransfer's for those pairs. values[i][k] for sender senders[i][k].
std::vector<std::vector<double>> linkedAverages(IlluminanceEngine& engine, const ReceiverPoints& at,
                                                const std::vector<std::vector<int>>& senders,
                                                const std::vector<std::size_t>& receivers,
                                                std::size_t firstElement) {
  std::vector<std::vector<double>> values(at.start.size() - 1);
  std::vector<SamplePoint> points;
  std::vector<double> weights;
  std::vector<cl_int> start = {0}, faces, owner;
  const auto flush = [&] {
    if (faces.empty()) return;
    const std::vector<float> e = engine.linkedIlluminance(points, start, faces, nullptr, owner);
    for (std::size_t w = 0; w + 1 < start.size(); ++w) {
      const auto i = static_cast<std::size_t>(owner[w]);
      for (cl_int k = start[w]; k < start[w + 1]; ++k) {
        double sum = 0.0;
        for (std::size_t lane = 0; lane < PN_LANES; ++lane)
          sum += weights[w * PN_LANES + lane] * e[static_cast<std::size_t>(k) * PN_LANES + lane];
        values[i][static_cast<std::size_t>(k - start[w])] += sum;
      }
    }
    points.clear(), weights.clear(), start.assign(1, 0), faces.clear(), owner.clear();
  };
  for (std::size_t i : receivers) {
    values[i].assign(senders[i].size(), 0.0);
    if (senders[i].empty()) continue;
    const std::size_t first = at.start[i], count = at.start[i + 1] - first;
    const std::size_t items = (count + PN_LANES - 1) / PN_LANES;
    if ((faces.size() + items * senders[i].size()) * PN_LANES > kTransferBatchValues) flush();
    // Work-items of PN_LANES points, the last padded with the last point at weight 0.
    for (std::size_t k = 0; k < items * PN_LANES; ++k) {
      points.push_back(at.points[first + std::min(k, count - 1)]);
      weights.push_back(k < count ? at.weights[first + k] : 0.0);
    }
    for (std::size_t w = 0; w < items; ++w) {
      for (int j : senders[i]) faces.push_back(static_cast<cl_int>(firstElement) + j);
      start.push_back(static_cast<cl_int>(faces.size()));
      owner.push_back(static_cast<cl_int>(i));
    }
  }
  flush();
  return values;
}

}  // namespace

Eigen::MatrixXd elementTransfer(IlluminanceEngine& engine, const SurfaceMesh& mesh,
                                const FarFieldRule& rule, std::size_t firstElement,
                                const Eigen::VectorXd* rowSums) {
  if (!(rule.farRatio > 0.0)) return elementTransfer(engine, mesh, firstElement);
  if (rowSums && static_cast<std::size_t>(rowSums->size()) != mesh.elements.size())
    throw std::logic_error("elementTransfer: one row sum per element");
  const std::size_t n = mesh.elements.size();
  Eigen::MatrixXd t = zeroTransfer(n);
  if (n == 0) return t;
  const FarPoints far(mesh);
  const ComputedPairs pairs =
      farPointTransfer(engine, mesh, far, firstElement, rowSums != nullptr, t);
  const SenderLists senders = senderLists(mesh, rule, pairs);
  const std::vector<std::vector<int>>& near = senders.near;
  std::vector<std::size_t> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = i;
  std::vector<std::vector<double>> averages =
      linkedAverages(engine, nodesOf(mesh), near, all, firstElement);
  // The far pairs too close for reciprocity that were computed at the other element's points,
  // computed again at the receiver's own, as the rest of its far field.
  const std::vector<std::vector<double>> own =
      linkedAverages(engine, far.view(), senders.ownPoints, all, firstElement);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < own[i].size(); ++k)
      t(static_cast<Eigen::Index>(i), senders.ownPoints[i][k]) = own[i][k];

  // Per receiver: the near senders' node averages in place of their far-point values, and the
  // far ones scaled so that the row sums to rowSums[i], or else to its sum over the far points.
  std::vector<std::size_t> again;
  std::vector<std::vector<int>> every(n);
  std::vector<char> isNear(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const auto row = static_cast<Eigen::Index>(i);
    double nearAtFarPoints = 0.0, nearAverage = 0.0, farAtFarPoints = 0.0;
    for (std::size_t k = 0; k < near[i].size(); ++k) {
      isNear[static_cast<std::size_t>(near[i][k])] = 1;
      nearAtFarPoints += t(row, near[i][k]);
      nearAverage += averages[i][k];
    }
    for (std::size_t j = 0; j < n; ++j)
      if (!isNear[j]) farAtFarPoints += t(row, static_cast<Eigen::Index>(j));
    for (int j : near[i]) isNear[static_cast<std::size_t>(j)] = 0;
    if (farAtFarPoints > 0.0) {
      // The far field's node average: the row's sum less the near field's average.
      const double sum = rowSums ? (*rowSums)[row] : farAtFarPoints + nearAtFarPoints;
      const double factor = (sum - nearAverage) / farAtFarPoints;
      if (!(factor >= 0.5 && factor <= 2.0)) {
        again.push_back(i);
        for (std::size_t j = 0; j < n; ++j) every[i].push_back(static_cast<int>(j));
        continue;
      }
      t.row(row) *= factor;
    }
    for (std::size_t k = 0; k < near[i].size(); ++k) t(row, near[i][k]) = averages[i][k];
  }
  if (!again.empty()) {
    averages = linkedAverages(engine, nodesOf(mesh), every, again, firstElement);
    for (std::size_t i : again)
      for (std::size_t j = 0; j < n; ++j)
        t(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = averages[i][j];
  }
  return t;
}

}  // namespace penumbra
