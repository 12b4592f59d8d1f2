#include "photometry/photometric_frame.hpp"

#include <cmath>
#include <numbers>

namespace penumbra::photometry {
namespace {

constexpr double kRad = std::numbers::pi / 180;
constexpr double kDeg = 180 / std::numbers::pi;

}  // namespace

Vec3 directionOf(PhotometricType type, const TableAngles& angles) {
  const double h = angles.horizontalDeg * kRad, v = angles.verticalDeg * kRad;
  switch (type) {
    case PhotometricType::C:
      return {std::sin(v) * std::cos(h), std::sin(v) * std::sin(h), -std::cos(v)};
    case PhotometricType::B:
      return {std::cos(h) * std::sin(v), std::sin(h), -std::cos(h) * std::cos(v)};
    case PhotometricType::A:
      return {std::sin(v), std::cos(v) * std::sin(h), -std::cos(v) * std::cos(h)};
  }
  return Vec3::Zero();
}

TableAngles anglesOf(PhotometricType type, const Vec3& d) {
  TableAngles angles;
  switch (type) {
    case PhotometricType::C: {
      angles.verticalDeg = std::atan2(std::hypot(d.x(), d.y()), -d.z()) * kDeg;
      double c = std::atan2(d.y(), d.x()) * kDeg;
      if (c < 0) c += 360;
      angles.horizontalDeg = c >= 360 ? 0 : c;
      break;
    }
    case PhotometricType::B:
      angles.horizontalDeg = std::atan2(d.y(), std::hypot(d.x(), d.z())) * kDeg;
      angles.verticalDeg = std::atan2(d.x(), -d.z()) * kDeg;
      break;
    case PhotometricType::A:
      angles.verticalDeg = std::atan2(d.x(), std::hypot(d.y(), d.z())) * kDeg;
      angles.horizontalDeg = std::atan2(d.y(), -d.z()) * kDeg;
      break;
  }
  return angles;
}

}  // namespace penumbra::photometry
