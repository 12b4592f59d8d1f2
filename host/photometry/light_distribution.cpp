#include "photometry/light_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "geometry/tolerance.hpp"

namespace penumbra::photometry {
namespace {

// One plane of the table: its angle and the index of the stored row it copies.
struct Plane {
  double angleDeg;
  std::size_t row;
};

double wrap360(double angle) {
  double a = std::fmod(angle, 360.0);
  if (a < 0) a += 360;
  return a >= 360 ? 0 : a;
}

// Adds the mirror image of every plane under `mirror`, unless a plane already lies there.
template <typename Mirror>
void addMirrored(std::vector<Plane>& planes, Mirror mirror) {
  const std::size_t n = planes.size();
  for (std::size_t i = 0; i < n; ++i) {
    const double image = mirror(planes[i].angleDeg);
    const bool present = std::any_of(planes.begin(), planes.end(), [&](const Plane& p) {
      return std::abs(p.angleDeg - image) < 1e-9;
    });
    if (!present) planes.push_back({image, planes[i].row});
  }
}

// The type C planes on [0, 360) from the stored ones and the symmetry.
std::vector<Plane> expandC(const std::vector<double>& stored, HorizontalSymmetry symmetry) {
  std::vector<Plane> planes;
  if (symmetry == HorizontalSymmetry::Rotational) return {{0.0, 0}};
  for (std::size_t i = 0; i < stored.size(); ++i) {
    // 360° is C0 again: a full table that lists both keeps the C0 row.
    const double angle = wrap360(stored[i]);
    const bool present = std::any_of(planes.begin(), planes.end(), [&](const Plane& p) {
      return std::abs(p.angleDeg - angle) < 1e-9;
    });
    if (!present) planes.push_back({angle, i});
  }
  switch (symmetry) {
    case HorizontalSymmetry::Quadrant:
      addMirrored(planes, [](double c) { return 180 - c; });
      addMirrored(planes, [](double c) { return wrap360(360 - c); });
      break;
    case HorizontalSymmetry::AboutC0C180:
      addMirrored(planes, [](double c) { return wrap360(360 - c); });
      break;
    case HorizontalSymmetry::AboutC90C270:
      addMirrored(planes, [](double c) { return wrap360(180 - c); });
      break;
    default:
      break;
  }
  return planes;
}

// An angle this close to an end of its axis (degrees) is that end: a direction along the edge of
// the measured range, turned into a luminaire's frame and back, must not flip between the table's
// last value and 0 by rounding.
constexpr double kEndToleranceDeg = Tolerance::kRelativeGeometry * 180.0;

// Index i with axis[i] <= x <= axis[i + 1] and the weight of axis[i + 1]; false outside.
bool locate(const std::vector<double>& axis, double x, std::size_t& i, double& t) {
  if (axis.size() == 1) {
    i = 0;
    t = 0;
    return std::abs(x - axis.front()) <= kEndToleranceDeg;
  }
  if (x < axis.front() && axis.front() - x <= kEndToleranceDeg) x = axis.front();
  if (x > axis.back() && x - axis.back() <= kEndToleranceDeg) x = axis.back();
  if (!(x >= axis.front() && x <= axis.back())) return false;
  i = static_cast<std::size_t>(std::upper_bound(axis.begin(), axis.end(), x) - axis.begin());
  i = std::min(i == 0 ? 0 : i - 1, axis.size() - 2);
  t = (x - axis[i]) / (axis[i + 1] - axis[i]);
  return true;
}

}  // namespace

LightDistribution::LightDistribution(const PhotometricData& data) : type_(data.type) {
  // The stored table as (plane, in-plane) rows: type B turns its planes with V.
  const bool planesAreVertical = type_ == PhotometricType::B;
  std::vector<double> storedPlanes =
      planesAreVertical ? data.verticalAnglesDeg : data.horizontalAnglesDeg;
  std::vector<double> storedInPlane =
      planesAreVertical ? data.horizontalAnglesDeg : data.verticalAnglesDeg;
  const auto stored = [&](std::size_t plane, std::size_t inPlane) {
    return planesAreVertical ? data.candelaAt(inPlane, plane) : data.candelaAt(plane, inPlane);
  };

  std::vector<Plane> planes;
  std::vector<std::pair<double, std::size_t>> inPlane;  // angle, stored index
  for (std::size_t i = 0; i < storedInPlane.size(); ++i) inPlane.emplace_back(storedInPlane[i], i);
  if (type_ == PhotometricType::C) {
    planes = expandC(storedPlanes, data.symmetry);
  } else {
    for (std::size_t i = 0; i < storedPlanes.size(); ++i) planes.push_back({storedPlanes[i], i});
    if (data.symmetry == HorizontalSymmetry::Lateral) {
      // H = 0..90 stored: I(-H) = I(H). H is the plane angle of type A and the in-plane angle of
      // type B.
      if (type_ == PhotometricType::A) {
        addMirrored(planes, [](double h) { return -h; });
      } else {
        for (std::size_t i = 0; i < storedInPlane.size(); ++i) {
          if (storedInPlane[i] != 0) inPlane.emplace_back(-storedInPlane[i], i);
        }
      }
    }
  }
  std::sort(planes.begin(), planes.end(),
            [](const Plane& a, const Plane& b) { return a.angleDeg < b.angleDeg; });
  std::sort(inPlane.begin(), inPlane.end());
  for (const Plane& p : planes) planes_.push_back(p.angleDeg);
  for (const auto& a : inPlane) inPlane_.push_back(a.first);
  candela_.reserve(planes_.size() * inPlane_.size());
  for (const Plane& p : planes) {
    for (const auto& a : inPlane) candela_.push_back(stored(p.row, a.second));
  }
}

double LightDistribution::interpolate(double planeDeg, double inPlaneDeg) const {
  std::size_t k = 0;
  double s = 0;
  if (!locate(inPlane_, inPlaneDeg, k, s)) return 0;
  const std::size_t n = inPlane_.size();
  const auto along = [&](std::size_t plane) {
    const double a = candela_[plane * n + k];
    if (s == 0 || n == 1) return a;
    return (1 - s) * a + s * candela_[plane * n + k + 1];
  };
  if (planes_.size() == 1) {
    return (periodicPlanes() || planeDeg == planes_.front()) ? along(0) : 0.0;
  }
  std::size_t j = 0;
  double t = 0;
  if (periodicPlanes()) {
    // Planes wrap: after the last comes the first again, 360° further on.
    const double c = wrap360(planeDeg);
    if (c >= planes_.back() || c < planes_.front()) {
      const double start = planes_.back();
      const double gap = planes_.front() + 360 - start;
      const double offset = c >= start ? c - start : c + 360 - start;
      t = offset / gap;
      const double a = along(planes_.size() - 1);
      return t == 0 ? a : (1 - t) * a + t * along(0);
    }
    locate(planes_, c, j, t);
  } else if (!locate(planes_, planeDeg, j, t)) {
    return 0;
  }
  const double a = along(j);
  return t == 0 ? a : (1 - t) * a + t * along(j + 1);
}

double LightDistribution::intensity(const TableAngles& angles) const {
  return type_ == PhotometricType::B ? interpolate(angles.verticalDeg, angles.horizontalDeg)
                                     : interpolate(angles.horizontalDeg, angles.verticalDeg);
}

double LightDistribution::intensity(const Vec3& direction) const {
  return intensity(anglesOf(type_, direction));
}

PeakIntensity LightDistribution::peak() const {
  PeakIntensity best;
  best.candela = -1;
  for (std::size_t j = 0; j < planes_.size(); ++j) {
    for (std::size_t k = 0; k < inPlane_.size(); ++k) {
      if (candela(j, k) <= best.candela) continue;
      best.candela = candela(j, k);
      best.at = type_ == PhotometricType::B ? TableAngles{inPlane_[k], planes_[j]}
                                            : TableAngles{planes_[j], inPlane_[k]};
    }
  }
  return best;
}

}  // namespace penumbra::photometry
