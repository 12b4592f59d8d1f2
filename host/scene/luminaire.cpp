#include "scene/luminaire.hpp"

#include <numbers>

#include "photometry/zonal_flux.hpp"

namespace penumbra {

Mat3 aimRotation(const LuminaireAim& aim) {
  constexpr double kRad = std::numbers::pi / 180.0;
  const Eigen::AngleAxisd rotate(aim.rotateDeg * kRad, Vec3::UnitZ());
  const Eigen::AngleAxisd tilt(aim.tiltDeg * kRad, Vec3::UnitX());
  return (rotate * tilt).toRotationMatrix();
}

double Luminaire::zonalFluxLm() const {
  return photometry::zonalFlux(*distribution) * intensityScale / maintenanceFactor;
}

std::string luminaireModelName(LuminaireModel model) {
  switch (model) {
    case LuminaireModel::Point:
      return "point";
  }
  return "point";
}

}  // namespace penumbra
