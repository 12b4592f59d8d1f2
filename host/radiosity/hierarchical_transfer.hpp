#pragma once
// The transfer between elements by hierarchical links (Hanrahan, Salzman & Aupperle 1991, on
// the element trees of element_tree.hpp): a receiving node and a sending node are joined by one
// link when the error of treating them as wholes — the sender at its area-average luminance, the
// receiver taking the link's average E on every part of it — is within the bound asked for, and
// are split otherwise, down to the leaves (where a link is the dense transfer's entry itself).
// Each link's value is the kernel's exact occluded contour integral from the sending node at
// 1 cd/m², averaged over the receiving node's quadrature nodes: the links replace the N×N
// matrix, and their number grows about linearly with the elements rather than quadratically.
#include <memory>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "engine/illuminance_engine.hpp"
#include "radiosity/element_tree.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct HierarchyOptions {
  // The bound on a link's estimated error, relative to the illuminance a whole hemisphere of
  // unit luminance gives (π lx): the form factor's bound A_q/(π d²) times the relative change of
  // the kernel across the larger node, size/d (d the gap between the nodes' bounding spheres).
  // 0 links leaf to leaf everywhere: the dense transfer.
  double linkError = 2e-4;
  int quadratureOrder = 4;  // nodes per axis of a receiving node (elementQuadrature)
  // No link joins a node whose longest edge is above this (m). The bound lets a node of size s
  // link only beyond about s/0.185 at 2e-3 (s/0.086 at 2e-4), so nodes above 2 m link only in
  // halls tens of metres across: there a cap at 2 m would leave every pair of 2 m nodes of the
  // floor and the ceiling a link, as many as the square of the floor area. A large node seen
  // past many solids overflows the kernel's room for occluders (PN_MAX_CONTOUR_EDGES) and has
  // its links split, as any receiver that overflows.
  double largestLinkedNode = 16.0;
  // Nodes share the shadow casters of their largest ancestor no longer than this (m; the
  // transfer's memory and set-up grow with the pieces rather than the nodes;
  // EmittingFaceShadows::casterOwner); nodes above it have their own. Off: each node its own,
  // the dense transfer's casters and floats.
  double largestCasterOwner = 2.0;
  bool shareCasters = true;
};

// The links of a tree, receiver by receiver (compressed rows over all tree nodes).
struct NodeLinks {
  std::vector<std::size_t> start;  // node p's links: [start[p], start[p + 1])
  std::vector<int> source;         // the sending node of each link
  std::vector<double> transfer;    // lx at the receiver (its average) per cd/m² of the sender
};

class HierarchicalTransfer {
 public:
  // Builds the links of `tree` (which must outlive this object) and evaluates them with the
  // kernel on `device`, every tree node a unit source among `scene`'s solids.
  HierarchicalTransfer(compute::Device& device, const Scene& scene, const ElementTree& tree,
                       const HierarchyOptions& options, const EngineOptions& engine);
  ~HierarchicalTransfer();

  const NodeLinks& links() const { return links_; }
  // Values per leaf (rows in leaf order) as values per tree node: each node its leaves' area
  // average.
  Eigen::MatrixXd nodeAverages(const Eigen::MatrixXd& leafValues) const;
  const ElementTree& tree() const { return *tree_; }

  // Σ_q E_q(P)·luminance(q, c) at every point for every column c, each point's sources the
  // nodes its group of PN_LANES points links to by the same error bound: points × columns, lx.
  // `luminance` has one row per tree node (cd/m²; a node above the leaves at its leaves' area
  // average).
  Eigen::MatrixXd gather(std::span<const SamplePoint> points, const Eigen::MatrixXd& luminance);

 private:
  const ElementTree* tree_;
  HierarchyOptions options_;
  double tolerance_;
  std::vector<Plane> planes_;  // each tree node's plane
  Scene nodeScene_;            // every tree node as a source of 1 cd/m²
  std::unique_ptr<IlluminanceEngine> engine_;
  NodeLinks links_;
};

// The radiosity equations on the tree's leaves, solved through the links (push-pull: each
// node's gathered E reaches every leaf below it; a node's luminance is its leaves' area average)
// by Jacobi iteration to a relative residual of 1e-10. `direct` per leaf and channel (lx).
// Returns per leaf: indirect E (lx) and luminance (cd/m²) per channel; `residual` the final
// relative residual, `iterations` the sweeps taken.
struct HierarchicalSolution {
  Eigen::MatrixX3d indirect, luminance;  // per leaf
  Eigen::MatrixX3d nodeLuminance;        // per tree node
  double residual = 0.0;
  int iterations = 0;
};
HierarchicalSolution solveHierarchical(const HierarchicalTransfer& transfer,
                                       const Eigen::MatrixX3d& direct);

}  // namespace penumbra
