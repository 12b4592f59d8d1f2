#pragma once
// Quadrature rules over an element (a small convex polygon): points and area weights that
// average a function over it. The function averaged is the illuminance from another element,
// which is smooth inside but whose derivative grows like log(distance) at an edge shared with
// a face at an angle (a wall's element next to the floor). The rules therefore put their nodes
// closer to the edges than Gauss-Legendre does: each axis is mapped by x = 3s² - 2s³, whose
// derivative vanishes at both ends, which turns an x·log x end into s³·log s.
#include <vector>

#include "geometry/convex_polygon.hpp"

namespace penumbra {

struct QuadratureNode {
  Vec3 position = Vec3::Zero();
  double weight = 0.0;  // fraction of the element's area: the weights of an element sum to 1
};

// `order` nodes per axis: a parallelogram gets order² nodes, any other polygon order² per
// triangle of its fan. order >= 1.
std::vector<QuadratureNode> elementQuadrature(const ConvexPolygon& element, int order);

// Whether `polygon` is a parallelogram (opposite edges equal to 1e-12 of its diagonals).
bool isParallelogram(const ConvexPolygon& polygon);

// Gauss-Legendre nodes and weights on [0, 1] (weights sum to 1).
struct GaussRule {
  std::vector<double> nodes, weights;
};
GaussRule gaussLegendre01(int order);

}  // namespace penumbra
