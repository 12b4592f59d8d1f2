#include "glare/position_index.hpp"

#include <cmath>
#include <numbers>

namespace penumbra {

SightFrame SightFrame::along(const Vec3& look) {
  SightFrame frame;
  frame.forward = look.normalized();
  frame.right = frame.forward.cross(Vec3::UnitZ()).normalized();
  frame.up = frame.right.cross(frame.forward);
  return frame;
}

SourcePosition sourcePosition(const SightFrame& sight, const Vec3& toSource) {
  return SourcePosition{toSource.dot(sight.forward), toSource.dot(sight.up),
                        std::abs(toSource.dot(sight.right))};
}

std::optional<double> guthPositionIndex(const SourcePosition& position) {
  const double r = position.along, h = position.above, t = position.across;
  if (!(r > 0.0) || h < 0.0) return std::nullopt;
  if (h > kGuthMaxHeightRatio * r || t > kGuthMaxLateralRatio * r) return std::nullopt;
  constexpr double kDegrees = 180.0 / std::numbers::pi;
  const double tau = std::atan2(t, h) * kDegrees;  // 90° for a source level with the eye
  const double sigma = std::atan2(std::hypot(h, t), r) * kDegrees;
  const double linear = (35.2 - 0.31889 * tau - 1.22 * std::exp(-2.0 * tau / 9.0)) * 1e-3;
  const double quadratic = (21.0 + 0.26667 * tau - 0.002963 * tau * tau) * 1e-5;
  return std::exp(linear * sigma + quadratic * sigma * sigma);
}

}  // namespace penumbra
