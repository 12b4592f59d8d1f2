#include "radiosity/hierarchical_transfer.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/bounding_box.hpp"
#include "geometry/morton_order.hpp"
#include "geometry/tolerance.hpp"
#include "kernels/shared_types.h"
#include "radiosity/element_ball.hpp"
#include "radiosity/element_quadrature.hpp"
#include "radiosity/element_transfer.hpp"

namespace penumbra {

namespace {

constexpr double kPi = std::numbers::pi;

// The link's error bound (HierarchyOptions::linkError) between a receiver in ball `p` of size
// `pSize` and the sending node `q`: infinite where the balls meet.
double linkErrorBound(const Ball& p, double pSize, const Ball& q, double qSize, double qArea) {
  const double gap = (p.centre - q.centre).norm() - p.radius - q.radius;
  if (!(gap > 0.0)) return INFINITY;
  return qArea / (kPi * gap * gap) * std::max(pSize, qSize) / gap;
}

// Every tree node as an element (what elementScene makes unit sources of): node n is source n.
SurfaceMesh allNodes(const ElementTree& tree) {
  SurfaceMesh mesh;
  mesh.elements.reserve(tree.nodes.size());
  for (const ElementNode& node : tree.nodes) mesh.elements.push_back(node.element);
  return mesh;
}

// Links of one work-item's points or one receiving node: the sending nodes, and their values.
struct LinkBatch {
  std::vector<SamplePoint> points;  // work-items of PN_LANES
  std::vector<double> weights;      // per point (0 on padding)
  std::vector<cl_int> start = {0};  // per work-item
  std::vector<cl_int> faces;        // the sending node of each link
  std::vector<std::size_t> owner;   // per work-item: the receiver (node or point group)

  std::size_t values() const { return faces.size() * PN_LANES; }
  void clear() {
    points.clear(), weights.clear(), start.assign(1, 0), faces.clear(), owner.clear();
  }
};

// About 2^22 values (16 MB of float) per launch.
constexpr std::size_t kBatchValues = std::size_t{1} << 22;

PlanePolygon nodePlanePolygon(const ElementTree& tree, std::span<const Plane> planes, int node) {
  return PlanePolygon{tree.nodes[node].element.polygon, planes[node]};
}

// Replaces every sender above the leaves by those of its children the receiver `p` can exchange
// light with (p < 0: a group of points, which takes every child). False when every sender is a
// leaf already.
bool splitSenders(const ElementTree& tree, std::span<const Plane> planes, int p,
                  std::vector<int>& senders, double tolerance) {
  std::vector<int> next;
  bool split = false;
  for (int q : senders) {
    const ElementNode& Q = tree.nodes[q];
    if (Q.isLeaf()) {
      next.push_back(q);
      continue;
    }
    split = true;
    for (int c = Q.firstChild; c < Q.firstChild + Q.childCount; ++c)
      if (p < 0 || canExchange(nodePlanePolygon(tree, planes, p), nodePlanePolygon(tree, planes, c),
                               tolerance))
        next.push_back(c);
  }
  senders = std::move(next);
  return split;
}

// The kernel's own message for receiver p's overflow: its links evaluated once more, throwing.
std::string overflowMessage(IlluminanceEngine& engine, const ElementTree& tree, int p,
                            const std::vector<int>& senders, int order) {
  const SurfaceElement& element = tree.nodes[p].element;
  const std::vector<QuadratureNode> nodes = elementQuadrature(element.polygon, order);
  const std::size_t items = (nodes.size() + PN_LANES - 1) / PN_LANES;
  std::vector<SamplePoint> points;
  for (std::size_t i = 0; i < items * PN_LANES; ++i)
    points.push_back(SamplePoint{nodes[std::min(i, nodes.size() - 1)].position,
                                 element.polygon.normal(), element.solid});
  std::vector<cl_int> start = {0}, faces;
  for (std::size_t w = 0; w < items; ++w) {
    faces.insert(faces.end(), senders.begin(), senders.end());
    start.push_back(static_cast<cl_int>(faces.size()));
  }
  try {
    engine.linkedIlluminance(points, start, faces);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "the illuminance kernel ran out of room";
}

}  // namespace

HierarchicalTransfer::HierarchicalTransfer(compute::Device& device, const Scene& scene,
                                           const ElementTree& tree, const HierarchyOptions& options,
                                           const EngineOptions& engine)
    : tree_(&tree), options_(options), tolerance_(Tolerance::forSceneSize(scene.size()).length) {
  const std::size_t n = tree.nodes.size();
  std::vector<Ball> balls(n);
  for (std::size_t i = 0; i < n; ++i) balls[i] = ballOf(tree.nodes[i].element.polygon);
  planes_.resize(n);
  for (std::size_t i = 0; i < n; ++i) planes_[i] = tree.nodes[i].element.polygon.plane();

  // The links, receiver root by receiver root in parallel, each root's list its own: joined in
  // root order, so they do not depend on the thread count.
  std::vector<std::vector<std::pair<int, int>>> byRoot(tree.roots.size());
  tbb::parallel_for(std::size_t{0}, tree.roots.size(), [&](std::size_t r) {
    std::vector<std::pair<int, int>>& out = byRoot[r];
    std::vector<std::pair<int, int>> stack;
    for (int q : tree.roots) stack.emplace_back(tree.roots[r], q);
    while (!stack.empty()) {
      const auto [p, q] = stack.back();
      stack.pop_back();
      const ElementNode& P = tree.nodes[p];
      const ElementNode& Q = tree.nodes[q];
      if (p == q || !canExchange(nodePlanePolygon(tree, planes_, p),
                                 nodePlanePolygon(tree, planes_, q), tolerance_))
        continue;
      const bool small =
          P.size <= options_.largestLinkedNode && Q.size <= options_.largestLinkedNode;
      if ((P.isLeaf() && Q.isLeaf()) ||
          (small && linkErrorBound(balls[p], P.size, balls[q], Q.size, Q.element.area) <=
                        options_.linkError)) {
        out.emplace_back(p, q);
        continue;
      }
      const bool splitReceiver = Q.isLeaf() || (!P.isLeaf() && P.element.area >= Q.element.area);
      if (splitReceiver)
        for (int c = P.firstChild; c < P.firstChild + P.childCount; ++c) stack.emplace_back(c, q);
      else
        for (int c = Q.firstChild; c < Q.firstChild + Q.childCount; ++c) stack.emplace_back(p, c);
    }
  });
  std::vector<std::vector<int>> senders(n);
  for (auto& list : byRoot) {
    for (const auto& [p, q] : list) senders[static_cast<std::size_t>(p)].push_back(q);
    std::vector<std::pair<int, int>>().swap(list);  // each link held once from here on
  }

  nodeScene_ = elementScene(scene, allNodes(tree));
  // Each node shares the shadow casters of its highest ancestor no larger than
  // largestCasterOwner: the casters are built per such node, a few per piece, rather than per
  // node (EmittingFaceShadows::casterOwner says why that stays exact).
  for (std::size_t i = 0; i < n && options_.shareCasters; ++i) {
    int owner = static_cast<int>(i);
    for (int up = tree.nodes[i].parent;
         up >= 0 && tree.nodes[up].size <= options_.largestCasterOwner; up = tree.nodes[up].parent)
      owner = up;
    if (owner != static_cast<int>(i)) nodeScene_.sources[i].castersOf = owner;
  }
  engine_ = std::make_unique<IlluminanceEngine>(device, nodeScene_, engine);

  // Each receiving node's quadrature nodes, in work-items of PN_LANES (the last padded with its
  // last node at weight 0), each work-item linked to the node's senders. A receiver whose
  // occluders overflow the kernel's room has its links to nodes above the leaves split into
  // their children's, and is evaluated again.
  std::vector<std::vector<double>> values(n);
  std::vector<std::size_t> pending;
  for (std::size_t p = 0; p < n; ++p)
    if (!senders[p].empty()) pending.push_back(p);
  while (!pending.empty()) {
    std::vector<std::size_t> overflowed;
    LinkBatch batch;
    const auto flush = [&] {
      if (!batch.faces.empty()) {
        std::vector<int> overflow;
        std::vector<cl_int> receiver(batch.owner.begin(), batch.owner.end());
        const std::vector<float> e =
            engine_->linkedIlluminance(batch.points, batch.start, batch.faces, &overflow, receiver);
        for (std::size_t w = 0; w < batch.owner.size(); ++w) {
          const std::size_t p = batch.owner[w];
          if (overflow[w] != 0) {
            if (overflowed.empty() || overflowed.back() != p) overflowed.push_back(p);
            continue;
          }
          for (cl_int k = batch.start[w]; k < batch.start[w + 1]; ++k) {
            double sum = 0.0;
            for (std::size_t lane = 0; lane < PN_LANES; ++lane)
              sum += batch.weights[w * PN_LANES + lane] *
                     e[static_cast<std::size_t>(k) * PN_LANES + lane];
            values[p][static_cast<std::size_t>(k - batch.start[w])] += sum;
          }
        }
      }
      batch.clear();
    };
    for (std::size_t p : pending) {
      values[p].assign(senders[p].size(), 0.0);
      const SurfaceElement& element = tree.nodes[p].element;
      const std::vector<QuadratureNode> nodes =
          elementQuadrature(element.polygon, options_.quadratureOrder);
      const Vec3 normal = element.polygon.normal();
      const std::size_t items = (nodes.size() + PN_LANES - 1) / PN_LANES;
      if (batch.values() + items * senders[p].size() * PN_LANES > kBatchValues) flush();
      for (std::size_t i = 0; i < items * PN_LANES; ++i) {
        const QuadratureNode& q = nodes[std::min(i, nodes.size() - 1)];
        batch.points.push_back(SamplePoint{q.position, normal, element.solid});
        batch.weights.push_back(i < nodes.size() ? q.weight : 0.0);
      }
      for (std::size_t w = 0; w < items; ++w) {
        batch.faces.insert(batch.faces.end(), senders[p].begin(), senders[p].end());
        batch.start.push_back(static_cast<cl_int>(batch.faces.size()));
        batch.owner.push_back(p);
      }
    }
    flush();
    pending.clear();
    for (std::size_t p : overflowed) {
      if (!splitSenders(tree, planes_, static_cast<int>(p), senders[p], tolerance_)) {
        // Leaves only: as the dense transfer would, say which point overflowed.
        values[p].clear();
        throw std::runtime_error(overflowMessage(*engine_, tree, static_cast<int>(p), senders[p],
                                                 options_.quadratureOrder));
      }
      pending.push_back(p);
    }
  }

  links_.start.assign(n + 1, 0);
  for (std::size_t p = 0; p < n; ++p) links_.start[p + 1] = links_.start[p] + senders[p].size();
  links_.source.reserve(links_.start[n]);
  links_.transfer.reserve(links_.start[n]);
  for (std::size_t p = 0; p < n; ++p) {
    links_.source.insert(links_.source.end(), senders[p].begin(), senders[p].end());
    links_.transfer.insert(links_.transfer.end(), values[p].begin(), values[p].end());
    std::vector<int>().swap(senders[p]);
    std::vector<double>().swap(values[p]);
  }
}

HierarchicalTransfer::~HierarchicalTransfer() = default;

Eigen::MatrixXd HierarchicalTransfer::gather(std::span<const SamplePoint> given,
                                             const Eigen::MatrixXd& luminance) {
  const ElementTree& tree = *tree_;
  Eigen::MatrixXd e =
      Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(given.size()), luminance.cols());
  if (given.empty() || tree.nodes.empty()) return e;
  // Groups of PN_LANES points in Morton order: small groups link to coarse nodes sooner.
  const std::vector<std::size_t> order = mortonOrder(given);
  std::vector<SamplePoint> sorted(given.size());
  for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = given[order[i]];
  const std::span<const SamplePoint> points(sorted);
  std::vector<Ball> balls(tree.nodes.size());
  for (std::size_t i = 0; i < tree.nodes.size(); ++i)
    balls[i] = ballOf(tree.nodes[i].element.polygon);
  const std::vector<Plane>& planes = planes_;
  const std::size_t items = (points.size() + PN_LANES - 1) / PN_LANES;
  // Each work-item's senders: the same oracle as the links, the group's points as the receiver.
  std::vector<std::vector<cl_int>> senders(items);
  tbb::parallel_for(std::size_t{0}, items, [&](std::size_t w) {
    BoundingBox box;
    const std::size_t first = w * PN_LANES, end = std::min(points.size(), first + PN_LANES);
    for (std::size_t i = first; i < end; ++i) box.add(points[i].position);
    const Ball group{0.5 * (box.lo + box.hi), 0.5 * (box.hi - box.lo).norm()};
    std::vector<int> stack(tree.roots.rbegin(), tree.roots.rend());
    while (!stack.empty()) {
      const int q = stack.back();
      stack.pop_back();
      const ElementNode& Q = tree.nodes[q];
      bool inFront = false;  // the node emits towards its front only
      for (std::size_t i = first; i < end && !inFront; ++i)
        inFront = planes[q].signedDistance(points[i].position) > tolerance_;
      if (!inFront) continue;
      if (Q.isLeaf() || (Q.size <= options_.largestLinkedNode &&
                         linkErrorBound(group, 2.0 * group.radius, balls[q], Q.size,
                                        Q.element.area) <= options_.linkError)) {
        senders[w].push_back(q);
        continue;
      }
      for (int c = Q.firstChild + Q.childCount - 1; c >= Q.firstChild; --c) stack.push_back(c);
    }
  });
  std::vector<SamplePoint> padded;
  std::vector<cl_int> start = {0}, faces;
  std::vector<std::size_t> overflowed;  // work-items whose senders are split and gathered again
  // The work-items to gather, in batches; those that overflowed come round again.
  std::vector<std::size_t> pending(items);
  for (std::size_t w = 0; w < items; ++w) pending[w] = w;
  while (!pending.empty()) {
    overflowed.clear();
    std::vector<std::size_t> batchItems;
    const auto run = [&] {
      if (batchItems.empty()) return;
      std::vector<float> unit;
      std::vector<int> overflow;
      if (!faces.empty()) unit = engine_->linkedIlluminance(padded, start, faces, &overflow);
      for (std::size_t local = 0; local < batchItems.size(); ++local) {
        const std::size_t w = batchItems[local];
        if (!overflow.empty() && overflow[local] != 0) {
          if (!splitSenders(tree, planes_, -1, senders[w], tolerance_))
            engine_->linkedIlluminance(padded, start, faces);  // throws the kernel's message
          overflowed.push_back(w);
          continue;
        }
        for (cl_int k = start[local]; k < start[local + 1]; ++k)
          for (std::size_t lane = 0; lane < PN_LANES; ++lane) {
            const std::size_t point = w * PN_LANES + lane;
            if (point >= points.size()) break;
            const float value = unit[static_cast<std::size_t>(k) * PN_LANES + lane];
            if (value == 0.0f) continue;
            e.row(static_cast<Eigen::Index>(order[point])) += value * luminance.row(faces[k]);
          }
      }
      padded.clear(), start.assign(1, 0), faces.clear(), batchItems.clear();
    };
    for (std::size_t w : pending) {
      if ((faces.size() + senders[w].size()) * PN_LANES > kBatchValues) run();
      for (std::size_t lane = 0; lane < PN_LANES; ++lane)
        padded.push_back(points[std::min(w * PN_LANES + lane, points.size() - 1)]);
      faces.insert(faces.end(), senders[w].begin(), senders[w].end());
      start.push_back(static_cast<cl_int>(faces.size()));
      batchItems.push_back(w);
    }
    run();
    pending = overflowed;
  }
  return e;
}

Eigen::MatrixXd HierarchicalTransfer::nodeAverages(const Eigen::MatrixXd& leafValues) const {
  const ElementTree& tree = *tree_;
  const auto n = static_cast<Eigen::Index>(tree.nodes.size());
  Eigen::MatrixXd values = Eigen::MatrixXd::Zero(n, leafValues.cols());
  for (std::size_t l = 0; l < tree.leaves.size(); ++l)
    values.row(tree.leaves[l]) = leafValues.row(static_cast<Eigen::Index>(l));
  // Children come after their parent: from the last node back, each parent sees its children
  // done.
  for (Eigen::Index p = n - 1; p >= 0; --p) {
    const ElementNode& node = tree.nodes[p];
    if (node.isLeaf()) continue;
    double area = 0.0;
    for (int c = node.firstChild; c < node.firstChild + node.childCount; ++c) {
      values.row(p) += tree.nodes[c].element.area * values.row(c);
      area += tree.nodes[c].element.area;
    }
    values.row(p) /= area;
  }
  return values;
}

HierarchicalSolution solveHierarchical(const HierarchicalTransfer& transfer,
                                       const Eigen::MatrixX3d& direct) {
  const ElementTree& tree = transfer.tree();
  const NodeLinks& links = transfer.links();
  const auto n = static_cast<Eigen::Index>(tree.nodes.size());
  const auto leaves = static_cast<Eigen::Index>(tree.leaves.size());
  HierarchicalSolution solution;
  solution.indirect = Eigen::MatrixX3d::Zero(leaves, 3);
  solution.luminance = Eigen::MatrixX3d::Zero(leaves, 3);
  solution.nodeLuminance = Eigen::MatrixX3d::Zero(n, 3);
  Eigen::MatrixX3d scale(leaves, 3);  // ρ/π per leaf and channel
  for (Eigen::Index l = 0; l < leaves; ++l)
    scale.row(l) = tree.nodes[tree.leaves[l]].element.reflectance.transpose() / kPi;
  const Eigen::MatrixX3d b = scale.cwiseProduct(direct);  // the luminance of one reflection
  const double bNorm = b.norm();

  Eigen::MatrixX3d& nodeL = solution.nodeLuminance;
  const auto pull = [&](const Eigen::MatrixX3d& leafL) { nodeL = transfer.nodeAverages(leafL); };
  Eigen::MatrixX3d leafL = b, gathered(n, 3);
  constexpr double kTolerance = 1e-10;
  constexpr int kMaxIterations = 20000;
  for (int iteration = 1; iteration <= kMaxIterations; ++iteration) {
    pull(leafL);
    // Each node gathers along its links, then passes what it gathered to every node below it.
    for (Eigen::Index p = 0; p < n; ++p) {
      Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
      for (std::size_t k = links.start[p]; k < links.start[p + 1]; ++k)
        sum += links.transfer[k] * nodeL.row(links.source[k]);
      const int parent = tree.nodes[p].parent;
      gathered.row(p) = parent >= 0 ? Eigen::RowVector3d(sum + gathered.row(parent)) : sum;
    }
    for (Eigen::Index l = 0; l < leaves; ++l)
      solution.indirect.row(l) = gathered.row(tree.leaves[l]);
    const Eigen::MatrixX3d next = b + scale.cwiseProduct(solution.indirect);
    solution.residual = bNorm > 0.0 ? (next - leafL).norm() / bNorm : 0.0;
    solution.iterations = iteration;
    leafL = next;
    if (solution.residual <= kTolerance) break;
  }
  solution.luminance = leafL;
  pull(leafL);
  return solution;
}

}  // namespace penumbra
