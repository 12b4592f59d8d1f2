#pragma once
// An independent reference for daylight through a window, written apart from the product's
// closed forms: E at a point in a room from the sky and the ground seen through a rectangular
// window in the wall y = 0 (room side y = 0, outside y = −wall), by the definition
//   E = ∫ L(ω) (n·ω)⁺ cos θ_s / d² dA
// over the part of the window's outer rectangle that the point sees through its room-side
// rectangle. For a point in the room the reveals leave exactly the outer rectangle intersected
// with the room-side rectangle projected from the point onto the outer plane. L is the sky's
// (uniform, or CIE overcast: L_z (1 + 2 sin α)/3) above the point's horizontal and the ground's
// below; the integrand is smooth on each side, so the rectangle is cut at the point's height and
// each part takes an order × order Gauss–Legendre rule.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "geometry/vec.hpp"
#include "radiosity/element_quadrature.hpp"
#include "scene/scene.hpp"

namespace penumbra::testing {

struct WallWindow {
  double x0 = 0.0, x1 = 0.0, z0 = 0.0, z1 = 0.0;  // the opening in the wall y = 0, m
  double wall = 0.2;                              // the wall's thickness, m
  double transmittance = 1.0;
};

// Gauss–Legendre nodes and weights on [a, b].
struct IntervalRule {
  std::vector<double> x, w;
};
// The cuts of a piecewise-smooth integrand on [lo, hi]: clamped into it, sorted, repeats removed,
// so that consecutive cuts bound the pieces a rule integrates one at a time.
inline void piecesWithin(std::vector<double>& cuts, double lo, double hi) {
  for (double& c : cuts) c = std::clamp(c, lo, hi);
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
}

inline IntervalRule gaussLegendreOn(int n, double a, double b) {
  const GaussRule unit = gaussLegendre01(n);
  IntervalRule r;
  for (std::size_t k = 0; k < unit.nodes.size(); ++k) {
    r.x.push_back(a + (b - a) * unit.nodes[k]);
    r.w.push_back((b - a) * unit.weights[k]);
  }
  return r;
}

// E (lx) at p (unit normal n, p.y() > 0: in the room) through `window`; 0 on the window's wall.
inline double windowSkyQuadrature(const Sky& sky, const WallWindow& window, const Vec3& p,
                                  const Vec3& n, int order = 96) {
  if (p.y() <= 0.0) return 0.0;
  const double k = (p.y() + window.wall) / p.y();  // the room-side rectangle, projected from p
  const double x0 = std::max(window.x0, p.x() + (window.x0 - p.x()) * k);
  const double x1 = std::min(window.x1, p.x() + (window.x1 - p.x()) * k);
  const double z0 = std::max(window.z0, p.z() + (window.z0 - p.z()) * k);
  const double z1 = std::min(window.z1, p.z() + (window.z1 - p.z()) * k);
  if (x1 <= x0 || z1 <= z0) return 0.0;
  const double lz = sky.zenithLuminance(), lg = sky.groundLuminance();
  const auto luminance = [&](double sinAltitude, bool above) {
    if (!above) return lg;
    return sky.model == SkyModel::CieOvercast ? lz * (1.0 + 2.0 * sinAltitude) / 3.0 : lz;
  };
  double e = 0.0;
  const double cuts[] = {z0, std::clamp(p.z(), z0, z1), z1};
  for (int part = 0; part < 2; ++part) {
    if (cuts[part + 1] <= cuts[part]) continue;
    const IntervalRule u = gaussLegendreOn(order, x0, x1);
    const IntervalRule v = gaussLegendreOn(order, cuts[part], cuts[part + 1]);
    for (std::size_t i = 0; i < u.x.size(); ++i)
      for (std::size_t j = 0; j < v.x.size(); ++j) {
        const Vec3 d = Vec3(u.x[i], -window.wall, v.x[j]) - p;
        const double r = d.norm();
        const Vec3 omega = d / r;
        const double cosReceiver = std::max(0.0, n.dot(omega));
        const double cosSource = -omega.y();  // the outer rectangle emits along +y
        e += u.w[i] * v.w[j] * luminance(omega.z(), part == 1) * cosReceiver * cosSource / (r * r);
      }
  }
  return window.transmittance * e;
}

}  // namespace penumbra::testing
