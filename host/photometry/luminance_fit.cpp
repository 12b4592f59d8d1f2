#include "photometry/luminance_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "photometry/nonnegative_least_squares.hpp"
#include "photometry/photometric_frame.hpp"

namespace penumbra::photometry {
namespace {

struct Node {
  double cosPhi;   // to the nadir
  double candela;  // the table's value
};

std::vector<Node> tableNodes(const LightDistribution& d) {
  std::vector<Node> nodes;
  const std::vector<double>& planes = d.planeAnglesDeg();
  const std::vector<double>& inPlane = d.inPlaneAnglesDeg();
  for (std::size_t j = 0; j < planes.size(); ++j) {
    for (std::size_t k = 0; k < inPlane.size(); ++k) {
      const TableAngles angles = d.type() == PhotometricType::B
                                     ? TableAngles{inPlane[k], planes[j]}
                                     : TableAngles{planes[j], inPlane[k]};
      const Vec3 direction = directionOf(d.type(), angles);
      nodes.push_back({-direction.z(), d.candela(j, k)});
    }
  }
  return nodes;
}

// The largest |A cos φ L − I| over every node, relative to the peak.
double peakRelativeErrorOf(const LuminanceFit& fit, const std::vector<Node>& nodes, double peak) {
  double worst = 0.0;
  for (const Node& node : nodes)
    worst = std::max(worst, std::abs(fit.intensity(node.cosPhi) - node.candela));
  return peak > 0.0 ? worst / peak : 0.0;
}

LuminanceFit fitOfOrder(const std::vector<Node>& nodes, double areaM2, double peak, int order) {
  std::vector<const Node*> front;
  for (const Node& node : nodes)
    if (node.cosPhi > 0.0) front.push_back(&node);
  LuminanceFit fit;
  fit.openingAreaM2 = areaM2;
  fit.coefficients.assign(static_cast<std::size_t>(order) + 1, 0.0);
  if (!front.empty()) {
    Eigen::MatrixXd design(front.size(), order + 1);
    Eigen::VectorXd target(front.size());
    for (std::size_t i = 0; i < front.size(); ++i) {
      double power = areaM2 * front[i]->cosPhi;
      for (int k = 0; k <= order; ++k) {
        design(static_cast<Eigen::Index>(i), k) = power;
        power *= front[i]->cosPhi;
      }
      target(static_cast<Eigen::Index>(i)) = front[i]->candela;
    }
    const Eigen::VectorXd c = design.colPivHouseholderQr().solve(target);
    for (int k = 0; k <= order; ++k) fit.coefficients[static_cast<std::size_t>(k)] = c(k);
  }
  fit.peakRelativeError = peakRelativeErrorOf(fit, nodes, peak);
  return fit;
}

// The nodes in front of the opening gathered by cos φ (the C planes of a type C table share
// their γ): the least squares of the fit over every node is that over these, each weighed by the
// square root of its count and aiming at its mean candela.
struct NodeGroup {
  double cosPhi;
  double weight;
  double meanCandela;
};

std::vector<NodeGroup> frontGroups(const std::vector<Node>& nodes) {
  std::map<double, std::pair<int, double>> byCosine;  // count, candela sum
  for (const Node& node : nodes) {
    if (node.cosPhi <= 0.0) continue;
    auto& [count, sum] = byCosine[node.cosPhi];
    ++count;
    sum += node.candela;
  }
  std::vector<NodeGroup> groups;
  for (const auto& [cosPhi, entry] : byCosine)
    groups.push_back(
        {cosPhi, std::sqrt(static_cast<double>(entry.first)), entry.second / entry.first});
  return groups;
}

// The fit Σ_k c_k cos^k φ, k = 0..highestPower, with every c_k >= 0 (nonnegative least squares),
// trimmed after its highest nonzero power.
LuminanceFit nonnegativeFit(const std::vector<Node>& nodes, const std::vector<NodeGroup>& groups,
                            double areaM2, double peak, int highestPower) {
  const auto rows = static_cast<Eigen::Index>(groups.size());
  Eigen::MatrixXd design(rows, highestPower + 1);
  Eigen::VectorXd target(rows);
  for (Eigen::Index i = 0; i < rows; ++i) {
    const NodeGroup& group = groups[static_cast<std::size_t>(i)];
    double power = group.weight * areaM2 * group.cosPhi;
    for (int k = 0; k <= highestPower; ++k) {
      design(i, k) = power;
      power *= group.cosPhi;
    }
    target(i) = group.weight * group.meanCandela;
  }
  const Eigen::VectorXd c = nonnegativeLeastSquares(design, target);
  LuminanceFit fit;
  fit.openingAreaM2 = areaM2;
  int highest = 0;
  for (int k = 0; k <= highestPower; ++k)
    if (c(k) > 0.0) highest = k;
  fit.coefficients.assign(c.data(), c.data() + highest + 1);
  fit.peakRelativeError = peakRelativeErrorOf(fit, nodes, peak);
  return fit;
}

// The nonnegative fit of the lowest highest power, from `lowestPower` up to kLuminanceFitMaxPower,
// within `tolerance`; nothing where none is.
std::optional<LuminanceFit> lowestNonnegativeFit(const std::vector<Node>& nodes, double areaM2,
                                                 double peak, double tolerance, int lowestPower) {
  const std::vector<NodeGroup> groups = frontGroups(nodes);
  if (groups.empty()) return std::nullopt;
  for (int power = lowestPower; power <= kLuminanceFitMaxPower; ++power) {
    LuminanceFit fit = nonnegativeFit(nodes, groups, areaM2, peak, power);
    if (fit.peakRelativeError <= tolerance) return fit;
  }
  return std::nullopt;
}

}  // namespace

double LuminanceFit::luminance(double cosPhi) const {
  double sum = 0.0;
  for (auto c = coefficients.rbegin(); c != coefficients.rend(); ++c) sum = sum * cosPhi + *c;
  return sum;
}

double LuminanceFit::conditioning() const {
  constexpr int kSteps = 1000;
  double largest = 0.0, sum = 0.0;
  for (int i = 0; i <= kSteps; ++i)
    largest = std::max(largest, std::abs(luminance(static_cast<double>(i) / kSteps)));
  for (double c : coefficients) sum += std::abs(c);
  return largest > 0.0 ? sum / largest : 1.0;
}

double LuminanceFit::intensity(double cosPhi) const {
  return cosPhi > 0.0 ? openingAreaM2 * cosPhi * luminance(cosPhi) : 0.0;
}

LuminanceFit fitLuminance(const LightDistribution& distribution, double areaM2, double tolerance,
                          int maxOrder) {
  const std::vector<Node> nodes = tableNodes(distribution);
  const double peak = distribution.peak().candela;
  LuminanceFit best;
  for (int order = 0; order <= maxOrder; ++order) {
    LuminanceFit fit = fitOfOrder(nodes, areaM2, peak, order);
    const bool integrable =
        fit.peakRelativeError <= tolerance && fit.conditioning() <= kLuminanceConditioningLimit;
    if (integrable) return fit;
    if (order == 0 || fit.peakRelativeError < best.peakRelativeError) best = std::move(fit);
  }
  if (std::optional<LuminanceFit> powers =
          lowestNonnegativeFit(nodes, areaM2, peak, tolerance, maxOrder + 1))
    return *std::move(powers);
  return best;
}

}  // namespace penumbra::photometry
