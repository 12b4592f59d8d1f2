#include "glare/ugr_table.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "geometry/convex_polygon.hpp"
#include "glare/glare_rating.hpp"
#include "glare/position_index.hpp"
#include "photometry/luminous_opening.hpp"
#include "photometry/zonal_flux.hpp"

namespace penumbra {

TabularLuminaire tabularLuminaire(const photometry::LightDistribution& distribution,
                                  const photometry::LuminousOpening& opening) {
  TabularLuminaire luminaire{&distribution, 0.0, {0.0, 0.0, 0.0, 0.0}};
  if (opening.shape == photometry::OpeningShape::RectangleWithLuminousSides) {
    luminaire.areaM2 = opening.lengthM * opening.widthM;
    for (int side = 0; side < 4; ++side) {
      // The C0 and C180 faces run along the width, the C90 and C270 faces along the length.
      const double along = side % 2 == 0 ? opening.widthM : opening.lengthM;
      luminaire.sideAreaM2[side] = along * opening.sideHeightsM[side];
    }
    return luminaire;
  }
  const std::vector<Vec3> outline = photometry::flatOutline(opening);
  if (!outline.empty()) luminaire.areaM2 = ConvexPolygon(outline).area();
  return luminaire;
}

double projectedArea(const TabularLuminaire& luminaire, const Vec3& toEye) {
  const double* side = luminaire.sideAreaM2;
  return luminaire.areaM2 * std::max(0.0, -toEye.z()) + side[0] * std::max(0.0, toEye.x()) +
         side[1] * std::max(0.0, toEye.y()) + side[2] * std::max(0.0, -toEye.x()) +
         side[3] * std::max(0.0, -toEye.y());
}

double arrayGlareSum(const TabularLuminaire& luminaire, const StandardRoom& room, Viewing viewing,
                     const UgrTableSettings& settings) {
  const double h = settings.heightM, spacing = settings.spacingRatio * h;
  const int across = static_cast<int>(std::lround(room.acrossH / settings.spacingRatio));
  const int along = static_cast<int>(std::lround(room.alongH / settings.spacingRatio));
  const double halfWidth = 0.5 * room.acrossH * h;
  double sum = 0.0;
  for (int i = 0; i < across; ++i) {
    const double t = -halfWidth + (i + 0.5) * spacing;
    for (int j = 0; j < along; ++j) {
      const double r = (j + 0.5) * spacing;
      const std::optional<double> p = guthPositionIndex({r, h, std::abs(t)});
      if (!p) continue;
      // From the luminaire to the eye, in the luminaire's frame (z up, C0 along x).
      const Vec3 toEye = viewing == Viewing::Crosswise ? Vec3(r, -t, -h) : Vec3(-t, -r, -h);
      const double intensity = luminaire.distribution->intensity(toEye);
      const double distance2 = r * r + t * t + h * h;
      const double projected = projectedArea(luminaire, toEye / std::sqrt(distance2));
      const double luminance = intensity / projected;
      const double omega = projected / distance2;
      sum += luminance * luminance * omega / (*p * *p);
    }
  }
  return sum;
}

UgrTable computeUgrTable(const TabularLuminaire& luminaire, const UgrTableSettings& settings) {
  if (luminaire.distribution == nullptr || !(luminaire.areaM2 > 0.0)) {
    throw std::invalid_argument("UGR table: the luminaire needs a flat luminous area");
  }
  UgrTable table;
  table.settings = settings;
  const ZonalCones cones = zonalCones(*luminaire.distribution);
  const double zonesFlux = cones.down + cones.up;  // the standard's Φ in B
  table.fluxLm = photometry::zonalFlux(*luminaire.distribution);
  const double h = settings.heightM;
  for (const StandardRoom& room : kStandardRooms) {
    UgrTableRow row;
    row.room = room;
    const double x = room.acrossH * h, y = room.alongH * h;
    const double k = x * y / (h * (x + y));
    const std::optional<GeometricMultipliers> multipliers = geometricMultipliers(k);
    if (!multipliers) throw std::logic_error("UGR table: a room index without CIE 190 multipliers");
    const FluxFractions fractions = fluxFractions(cones, *multipliers);
    row.luminaires = static_cast<int>(std::lround(room.acrossH / settings.spacingRatio) *
                                      std::lround(room.alongH / settings.spacingRatio));
    const double perWallArea = row.luminaires * zonesFlux / (2.0 * h * (x + y));  // B, lx
    const double crosswise = arrayGlareSum(luminaire, room, Viewing::Crosswise, settings);
    const double endwise = arrayGlareSum(luminaire, room, Viewing::Endwise, settings);
    for (std::size_t s = 0; s < kStandardReflectances.size(); ++s) {
      const WallTransfer transfer = wallTransfer(x, y, h, kStandardReflectances[s]);
      const double wallIndirect = perWallArea * (fractions.toFloor * transfer.fromFloor +
                                                 fractions.toWalls * transfer.fromWalls +
                                                 fractions.toCeiling * transfer.fromCeiling);
      const double background = wallIndirect / std::numbers::pi;
      row.backgroundLuminance[s] = background;
      constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
      row.crosswise[s] = unifiedGlareRating(crosswise, background).value_or(kNaN);
      row.endwise[s] = unifiedGlareRating(endwise, background).value_or(kNaN);
    }
    table.rows.push_back(row);
  }
  return table;
}

}  // namespace penumbra
