#include "radiosity/element_transfer.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

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
  Scene elements;
  elements.file = scene.file;
  elements.materials = scene.materials;
  elements.solids = scene.solids;
  elements.room = scene.room;
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

// t(i, j) for every receiver i and sender j (the engine's source firstElement + j): receiver i
// takes points[start[i] … start[i + 1]), and `average(values, i)` reduces sender j's values at
// them (values[k - start[i]] for point k) to t(i, j). Whole receivers per launch, about
// kTransferBatchValues values each, the launches pipelined (illuminanceBySourceBatches).
template <class Average>
void transferByBatches(IlluminanceEngine& engine, std::span<const SamplePoint> points,
                       std::span<const std::size_t> start, std::size_t firstElement,
                       Eigen::MatrixXd& t, const Average& average) {
  const std::size_t n = start.size() - 1;
  std::vector<std::size_t> firstOf;  // batch → its first receiver; one more entry, n
  for (std::size_t first = 0; first < n;) {
    firstOf.push_back(first);
    std::size_t last = first + 1;
    while (last < n && (start[last + 1] - start[first]) * n <= kTransferBatchValues) ++last;
    first = last;
  }
  firstOf.push_back(n);
  std::vector<std::span<const SamplePoint>> batches;
  for (std::size_t b = 0; b + 1 < firstOf.size(); ++b)
    batches.push_back(points.subspan(start[firstOf[b]], start[firstOf[b + 1]] - start[firstOf[b]]));
  engine.illuminanceBySourceBatches(
      batches, [&](std::size_t b, const std::vector<float>& e, std::size_t stride) {
        const std::size_t first = firstOf[b], last = firstOf[b + 1], begin = start[first];
        for (std::size_t j = 0; j < n; ++j) {
          const float* row = e.data() + (firstElement + j) * stride;
          for (std::size_t i = first; i < last; ++i)
            t(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
                average(row + (start[i] - begin), i);
        }
      });
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
                    [&](const float* values, std::size_t i) {
                      double sum = 0.0;
                      for (std::size_t k = 0; k < mesh.nodeStart[i + 1] - mesh.nodeStart[i]; ++k)
                        sum += mesh.weights[mesh.nodeStart[i] + k] * values[k];
                      return sum;
                    });
  return t;
}

namespace {

// Each receiver's near senders under `rule`, in increasing order: the elements it can exchange
// light with that are not far.
std::vector<std::vector<int>> nearSenders(const SurfaceMesh& mesh, const FarFieldRule& rule) {
  const std::size_t n = mesh.elements.size();
  std::vector<Ball> balls(n);
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  for (std::size_t i = 0; i < n; ++i) {
    balls[i] = ballOf(mesh.elements[i].polygon);
    lo = lo.cwiseMin(balls[i].centre - Vec3::Constant(balls[i].radius));
    hi = hi.cwiseMax(balls[i].centre + Vec3::Constant(balls[i].radius));
  }
  const double tolerance = Tolerance::forSceneSize((hi - lo).norm()).length;
  std::vector<std::vector<int>> near(n);
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
    const double diameter = 2.0 * balls[i].radius;
    for (std::size_t j = 0; j < n; ++j) {
      const double gap = ballGap(balls[i], balls[j]);
      const bool far = gap > 0.0 && (diameter / gap) * (diameter / gap) <= rule.farRatio;
      if (j != i && !far &&
          canExchange(mesh.elements[i].polygon, mesh.elements[j].polygon, tolerance))
        near[i].push_back(static_cast<int>(j));
    }
  });
  return near;
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

// t(i, j) = the mean of E from element j over element i's far points (farPoints), lx per
// cd/m², every pair.
void farPointTransfer(IlluminanceEngine& engine, const SurfaceMesh& mesh, std::size_t firstElement,
                      Eigen::MatrixXd& t) {
  std::vector<SamplePoint> points;
  std::vector<std::size_t> start = {0};
  for (const SurfaceElement& element : mesh.elements) {
    const std::vector<SamplePoint> own = farPoints(element);
    points.insert(points.end(), own.begin(), own.end());
    start.push_back(points.size());
  }
  transferByBatches(engine, points, start, firstElement, t,
                    [&](const float* values, std::size_t i) {
                      const std::size_t count = start[i + 1] - start[i];
                      double sum = 0.0;
                      for (std::size_t k = 0; k < count; ++k) sum += values[k];
                      return sum / static_cast<double>(count);
                    });
}

// The node average over receiver i of E from each of senders[i] (the receivers in `receivers`),
// by the kernel's linked launch: the same floats as illuminanceBySource, so the same sums as
// elementTransfer's for those pairs. values[i][k] for sender senders[i][k].
std::vector<std::vector<double>> nodeAverages(IlluminanceEngine& engine, const SurfaceMesh& mesh,
                                              const std::vector<std::vector<int>>& senders,
                                              const std::vector<std::size_t>& receivers,
                                              std::size_t firstElement) {
  std::vector<std::vector<double>> values(mesh.elements.size());
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
    const std::size_t first = mesh.nodeStart[i], count = mesh.nodeStart[i + 1] - first;
    const std::size_t items = (count + PN_LANES - 1) / PN_LANES;
    if ((faces.size() + items * senders[i].size()) * PN_LANES > kTransferBatchValues) flush();
    // Work-items of PN_LANES nodes, the last padded with the last node at weight 0.
    for (std::size_t k = 0; k < items * PN_LANES; ++k) {
      points.push_back(mesh.nodes[first + std::min(k, count - 1)]);
      weights.push_back(k < count ? mesh.weights[first + k] : 0.0);
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
                                const FarFieldRule& rule, std::size_t firstElement) {
  if (!(rule.farRatio > 0.0)) return elementTransfer(engine, mesh, firstElement);
  const std::size_t n = mesh.elements.size();
  Eigen::MatrixXd t = zeroTransfer(n);
  if (n == 0) return t;
  farPointTransfer(engine, mesh, firstElement, t);
  std::vector<std::vector<int>> near = nearSenders(mesh, rule);
  std::vector<std::size_t> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = i;
  std::vector<std::vector<double>> averages = nodeAverages(engine, mesh, near, all, firstElement);

  // Per receiver: the near senders' node averages in place of their far-point values, and the
  // far ones scaled so that the row keeps its sum over the far points.
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
      // The far field's node average: the row's far-point sum less the near field's average.
      const double factor = (farAtFarPoints + nearAtFarPoints - nearAverage) / farAtFarPoints;
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
    averages = nodeAverages(engine, mesh, every, again, firstElement);
    for (std::size_t i : again)
      for (std::size_t j = 0; j < n; ++j)
        t(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = averages[i][j];
  }
  return t;
}

}  // namespace penumbra
