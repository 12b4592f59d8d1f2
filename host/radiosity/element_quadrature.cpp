#include "radiosity/element_quadrature.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace penumbra {

GaussRule gaussLegendre01(int order) {
  if (order < 1) throw std::invalid_argument("quadrature order must be at least 1");
  // Newton's iteration on P_n from Chebyshev starting guesses; converges to round-off in a few
  // steps for every n used here (n <= 64).
  GaussRule rule;
  const int n = order;
  for (int i = 0; i < n; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
    double derivative = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      derivative = n * (x * p1 - p0) / (x * x - 1.0);
      const double step = p1 / derivative;
      x -= step;
      if (std::abs(step) < 1e-16) break;
    }
    rule.nodes.push_back(0.5 * (1.0 - x));
    rule.weights.push_back(1.0 / ((1.0 - x * x) * derivative * derivative));  // 2/(..)/2
  }
  return rule;
}

namespace {

// The axis map x = 3s² - 2s³ applied to a Gauss rule: nodes x(s_k), weights w_k·6 s_k (1 - s_k).
GaussRule edgeGraded(const GaussRule& gauss) {
  GaussRule rule;
  for (std::size_t k = 0; k < gauss.nodes.size(); ++k) {
    const double s = gauss.nodes[k];
    rule.nodes.push_back(s * s * (3.0 - 2.0 * s));
    rule.weights.push_back(gauss.weights[k] * 6.0 * s * (1.0 - s));
  }
  return rule;
}

}  // namespace

bool isParallelogram(const ConvexPolygon& polygon) {
  if (polygon.size() != 4) return false;
  const auto& v = polygon.vertices();
  const double scale = (v[2] - v[0]).norm() + (v[3] - v[1]).norm();
  return ((v[1] - v[0]) - (v[2] - v[3])).norm() <= 1e-12 * scale;
}

std::vector<QuadratureNode> elementQuadrature(const ConvexPolygon& element, int order) {
  const GaussRule rule = edgeGraded(gaussLegendre01(order));
  const std::vector<Vec3>& v = element.vertices();
  std::vector<QuadratureNode> nodes;
  if (isParallelogram(element)) {
    const Vec3 u = v[1] - v[0], w = v[3] - v[0];
    for (std::size_t a = 0; a < rule.nodes.size(); ++a)
      for (std::size_t b = 0; b < rule.nodes.size(); ++b)
        nodes.push_back(
            {v[0] + rule.nodes[a] * u + rule.nodes[b] * w, rule.weights[a] * rule.weights[b]});
    return nodes;
  }
  // A fan of triangles (v0, vi, vi+1), each as the square [0,1]² collapsed onto it:
  // p = v0 + s·(vi - v0) + s·t·(vi+1 - vi), area element 2·A·s.
  const double total = element.area();
  for (int i = 1; i + 1 < element.size(); ++i) {
    const Vec3 a = v[0], b = v[i], c = v[i + 1];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    for (std::size_t p = 0; p < rule.nodes.size(); ++p)
      for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
        const double s = rule.nodes[p], t = rule.nodes[q];
        nodes.push_back({a + s * (b - a) + s * t * (c - b),
                         2.0 * area * s * rule.weights[p] * rule.weights[q] / total});
      }
  }
  return nodes;
}

}  // namespace penumbra
