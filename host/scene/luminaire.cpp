#include "scene/luminaire.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/convex_polygon.hpp"
#include "photometry/luminous_opening.hpp"

#include "photometry/zonal_flux.hpp"

namespace penumbra {
namespace {

// The subdivided opening's cells are at most this size (m), and at most kMostParts along an axis:
// the point model of a cell meets its exact integral within 1 % beyond five times the cell's
// size (luminaire_area_test, AreaModelFarField).
constexpr double kPartSizeM = 0.05;
constexpr int kMostParts = 16;

int partsAlong(double size) {
  return std::clamp(static_cast<int>(std::ceil(size / kPartSizeM)), 1, kMostParts);
}

}  // namespace

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
    case LuminaireModel::Area:
      return "area";
  }
  return "point";
}

Vec3 LuminaireOpening::partCentre(int i, int j) const {
  return Vec3(((i + 0.5) / partsAlongLength - 0.5) * lengthM,
              ((j + 0.5) / partsAlongWidth - 0.5) * widthM, 0.0);
}

std::optional<LuminaireOpening> luminaireOpening(
    const photometry::LuminousOpening& shape, const photometry::LightDistribution& distribution) {
  std::vector<Vec3> outline = photometry::flatOutline(shape);
  if (outline.empty()) return std::nullopt;
  LuminaireOpening opening;
  opening.outline = std::move(outline);
  opening.lengthM = shape.lengthM;
  opening.widthM = shape.widthM;
  opening.fit = photometry::fitLuminance(distribution, ConvexPolygon(opening.outline).area());
  if (opening.fit.peakRelativeError > photometry::kLuminanceFitTolerance ||
      opening.fit.conditioning() > photometry::kLuminanceConditioningLimit) {
    opening.partsAlongLength = partsAlong(opening.lengthM);
    opening.partsAlongWidth = partsAlong(opening.widthM);
    if (!opening.subdivided()) opening.partsAlongLength = 2;
  }
  return opening;
}

}  // namespace penumbra
