#include "photometry/photometric_frame.hpp"

#include <cmath>

#include "geometry/angles.hpp"

namespace penumbra::photometry {

Vec3 directionOf(PhotometricType type, const TableAngles& angles) {
  const double h = angles.horizontalDeg * kRadiansPerDegree,
               v = angles.verticalDeg * kRadiansPerDegree;
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
      angles.verticalDeg = std::atan2(std::hypot(d.x(), d.y()), -d.z()) * kDegreesPerRadian;
      double c = std::atan2(d.y(), d.x()) * kDegreesPerRadian;
      if (c < 0) c += 360;
      angles.horizontalDeg = c >= 360 ? 0 : c;
      break;
    }
    case PhotometricType::B:
      angles.horizontalDeg = std::atan2(d.y(), std::hypot(d.x(), d.z())) * kDegreesPerRadian;
      angles.verticalDeg = std::atan2(d.x(), -d.z()) * kDegreesPerRadian;
      break;
    case PhotometricType::A:
      angles.verticalDeg = std::atan2(d.x(), std::hypot(d.y(), d.z())) * kDegreesPerRadian;
      angles.horizontalDeg = std::atan2(d.y(), -d.z()) * kDegreesPerRadian;
      break;
  }
  return angles;
}

}  // namespace penumbra::photometry
