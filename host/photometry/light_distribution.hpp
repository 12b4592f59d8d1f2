#pragma once
// The luminous intensity of a luminaire in every direction of its local frame
// (photometric_frame.hpp): the file's table expanded from its symmetry and interpolated
// bilinearly in the table's own two angles (docs/photometry.md).
//
// The table is held as planes (C for type C, V for type B, H for type A) and, in each plane, the
// angle within it (γ, H, V). Type C planes are periodic over 360°: the stored planes and their
// mirror images under the file's symmetry, in [0, 360). Types A and B cover the measured range
// only (their lateral symmetry mirrored); outside it, and outside the measured in-plane range
// (a downlight measured to γ = 90°), the intensity is 0.
//
// Bilinear interpolation keeps the table's values at its nodes exactly (the weights are 1 and 0
// there) and is continuous; between nodes it is linear in each angle.
#include <cstddef>
#include <vector>

#include "geometry/vec.hpp"
#include "photometry/photometric_data.hpp"
#include "photometry/photometric_frame.hpp"

namespace penumbra::photometry {

struct PeakIntensity {
  double candela = 0;
  TableAngles at;
};

class LightDistribution {
 public:
  explicit LightDistribution(const PhotometricData& data);

  PhotometricType type() const { return type_; }
  bool periodicPlanes() const { return type_ == PhotometricType::C; }
  const std::vector<double>& planeAnglesDeg() const { return planes_; }
  const std::vector<double>& inPlaneAnglesDeg() const { return inPlane_; }
  double candela(std::size_t plane, std::size_t inPlane) const {
    return candela_[plane * inPlane_.size() + inPlane];
  }

  // cd at the table's own angles (C and γ, or H and V); 0 outside the measured range.
  double intensity(const TableAngles& angles) const;
  // cd towards `direction` (local frame; need not be unit, must not be zero).
  double intensity(const Vec3& direction) const;

  // The largest value of the table and its angles (the first node that holds it).
  PeakIntensity peak() const;

 private:
  double interpolate(double planeDeg, double inPlaneDeg) const;

  PhotometricType type_;
  std::vector<double> planes_;   // increasing; type C in [0, 360)
  std::vector<double> inPlane_;  // increasing
  std::vector<double> candela_;  // planes_.size() x inPlane_.size()
};

}  // namespace penumbra::photometry
