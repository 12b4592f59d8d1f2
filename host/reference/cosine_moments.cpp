#include "reference/cosine_moments.hpp"

#include <cmath>

#include "reference/region_solid_angle.hpp"

namespace penumbra {

std::vector<double> cosineMoments(std::span<const VisibleArc> arcs, const Vec3& w, const Vec3& n,
                                  int order) {
  const std::size_t count = static_cast<std::size_t>(order) + 1;
  std::vector<double> sumW(count, 0.0), sumN(count, 0.0), f(count, 0.0);
  for (const VisibleArc& arc : arcs) {
    const Vec3 a = arc.from.normalized(), b = arc.to.normalized();
    const Vec3 normal = b.cross(a);
    const double s = normal.norm();
    if (s == 0.0) continue;
    const Vec3 m = normal / s;
    const Vec3 t = a.cross(m);  // unit, towards b
    const double theta = std::atan2(s, a.dot(b));
    const double x = w.dot(a), y = w.dot(t), r2 = x * x + y * y;
    const double c = std::cos(theta), sn = std::sin(theta);
    const double fEnd = x * c + y * sn, slopeEnd = -x * sn + y * c;  // f(Θ), f′(Θ)
    // [f^{k−1} f′]_0^Θ, with f(0) = x, f′(0) = y.
    double powEnd = 1.0, powStart = 1.0;  // f(Θ)^{k−1}, x^{k−1}
    f[0] = theta;
    for (std::size_t k = 1; k < count; ++k) {
      const double bracket = powEnd * slopeEnd - powStart * y;
      const double previous = k >= 2 ? (k - 1.0) * r2 * f[k - 2] : 0.0;
      f[k] = (previous - bracket) / static_cast<double>(k);
      powEnd *= fEnd;
      powStart *= x;
    }
    const double wm = w.dot(m), nm = n.dot(m);
    for (std::size_t k = 0; k < count; ++k) {
      sumW[k] += wm * f[k];
      sumN[k] += nm * f[k];
    }
  }
  // τ_0..τ_{order−1}.
  std::vector<double> tau(count, 0.0);
  tau[0] = regionSolidAngle(arcs, w);
  for (std::size_t k = 1; k + 1 < count; ++k) {
    const double previous = k >= 2 ? (k - 1.0) * tau[k - 2] : 0.0;
    tau[k] = (previous + sumW[k - 1]) / (k + 1.0);
  }
  const double wn = w.dot(n);
  std::vector<double> moments(count);
  for (std::size_t k = 0; k < count; ++k) {
    const double axial = k >= 1 ? static_cast<double>(k) * wn * tau[k - 1] : 0.0;
    moments[k] = (axial + sumN[k]) / (k + 2.0);
  }
  return moments;
}

}  // namespace penumbra
