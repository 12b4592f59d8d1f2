#include "radiosity/element_tree.hpp"

#include <stdexcept>

#include "geometry/tolerance.hpp"

namespace penumbra {

void ElementTree::split(int node, double tolerance) {
  if (!nodes[node].isLeaf()) throw std::logic_error("ElementTree::split: not a leaf");
  std::vector<ConvexPolygon> cells = halved(nodes[node].element.polygon, tolerance);
  if (cells.size() < 2) return;  // nothing left to halve: it stays a leaf
  const int first = static_cast<int>(nodes.size());
  for (ConvexPolygon& cell : cells) {
    ElementNode child;
    child.element = nodes[node].element;
    child.element.area = cell.area();
    child.size = longestEdge(cell);
    child.element.polygon = std::move(cell);
    child.parent = node;
    nodes.push_back(std::move(child));
  }
  nodes[node].firstChild = first;
  nodes[node].childCount = static_cast<int>(cells.size());
}

void ElementTree::numberLeaves() {
  leaves.clear();
  std::vector<int> stack;
  for (int root : roots) {
    stack.push_back(root);
    while (!stack.empty()) {
      const int n = stack.back();
      stack.pop_back();
      ElementNode& node = nodes[n];
      node.leaf = -1;
      if (node.isLeaf()) {
        node.leaf = static_cast<int>(leaves.size());
        leaves.push_back(n);
        continue;
      }
      for (int c = node.firstChild + node.childCount - 1; c >= node.firstChild; --c)
        stack.push_back(c);
    }
  }
}

SurfaceMesh ElementTree::leafMesh(int order) const {
  SurfaceMesh mesh;
  mesh.blackSolids = blackSolids;
  mesh.elements.reserve(leaves.size());
  for (int n : leaves) mesh.elements.push_back(nodes[n].element);
  placeNodes(mesh, order);
  return mesh;
}

ElementTree buildElementTree(const Scene& scene, double elementSize) {
  if (!(elementSize > 0.0)) throw std::invalid_argument("element size must be positive");
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  ElementTree tree;
  for (SurfacePiece& piece : surfacePieces(scene, tree.blackSolids)) {
    ElementNode root;
    root.size = longestEdge(piece.polygon);
    root.element = std::move(piece);
    tree.roots.push_back(static_cast<int>(tree.nodes.size()));
    tree.nodes.push_back(std::move(root));
  }
  // Breadth first: nodes appended while splitting are visited in turn.
  for (std::size_t n = 0; n < tree.nodes.size(); ++n)
    if (tree.nodes[n].size > elementSize) tree.split(static_cast<int>(n), tolerance);
  tree.numberLeaves();
  return tree;
}

}  // namespace penumbra
