#pragma once
// The surfaces as trees of elements, for the hierarchical transfer: each convex piece of a
// reflecting face (surfacePieces) is a root, halved (halved: a square into four) until its
// longest edge is at most the element size; the leaves are the elements the radiosity solves
// for, and every node above them is the union of its children, whose luminance is their area
// average. Links (link_refinement.hpp) join nodes at whatever level keeps the transfer's error
// within the bound asked for.
#include <string>
#include <vector>

#include "radiosity/surface_mesh.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct ElementNode {
  SurfaceElement element;
  double size = 0.0;    // longest edge, m
  int parent = -1;      // -1 for a root
  int firstChild = -1;  // children are nodes [firstChild, firstChild + childCount)
  int childCount = 0;
  int leaf = -1;  // index among the leaves (the mesh's elements), -1 above them

  bool isLeaf() const { return childCount == 0; }
};

struct ElementTree {
  std::vector<ElementNode> nodes;
  std::vector<int> roots;
  std::vector<int> leaves;  // node index of each leaf, in the mesh's element order
  std::vector<std::string> blackSolids;

  // Cuts leaf `node` into halves (halved); its children become leaves, it stops being one. Call
  // numberLeaves() after the last split.
  void split(int node, double tolerance);
  // Numbers the leaves depth first, root by root: leaves and ElementNode::leaf.
  void numberLeaves();
  // The leaves as a mesh (elements in leaf order) with `order` quadrature nodes per axis.
  SurfaceMesh leafMesh(int order) const;
};

// Every piece a root, split until every leaf's longest edge is at most `elementSize` (m).
ElementTree buildElementTree(const Scene& scene, double elementSize);

}  // namespace penumbra
