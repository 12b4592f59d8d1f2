#include "scene/luminaire_reader.hpp"

#include <cmath>
#include <string>

namespace penumbra::scenefile {
namespace {

// Angles of an aim beyond a full turn are almost always a typing slip (900 for 90).
constexpr double kLargestAimDeg = 360.0;

LuminaireAim readAim(const Reader& reader, const Field& field) {
  const MapView map = reader.map(field, "an aim {rotate_deg: .., tilt_deg: ..}");
  map.allowOnly({"rotate_deg", "tilt_deg"}, "an aim");
  LuminaireAim aim;
  const auto angle = [&](std::string_view key, double& to) {
    const std::optional<Field> f = map.find(key);
    if (!f) return;
    to = reader.number(*f);
    if (std::abs(to) > kLargestAimDeg) {
      reader.fail(f->where, "an aim angle lies in [-360, 360] degrees, got " + formatNumber(to));
    }
  };
  angle("rotate_deg", aim.rotateDeg);
  angle("tilt_deg", aim.tiltDeg);
  return aim;
}

void readArray(const Reader& reader, const Field& field, LuminaireSpec& spec) {
  const MapView map = reader.map(field, "an array {count: [nx, ny], spacing: [dx, dy]}");
  map.allowOnly({"count", "spacing"}, "an array");
  const Field count = map.require("count");
  const std::vector<double> n = reader.numbers(count, 2);
  for (double c : n) {
    if (c < 1 || c != std::floor(c) || c > 1000) {
      reader.fail(count.where,
                  "an array's counts are whole numbers from 1 to 1000, got " + formatNumber(c));
    }
  }
  spec.countX = static_cast<int>(n[0]);
  spec.countY = static_cast<int>(n[1]);
  const Field spacing = map.require("spacing");
  const std::vector<double> d = reader.numbers(spacing, 2);
  if (d[0] <= 0.0 || d[1] <= 0.0) {
    reader.fail(spacing.where, "an array's spacings must be greater than 0 m, got [" +
                                   formatNumber(d[0]) + ", " + formatNumber(d[1]) + "]");
  }
  spec.spacingX = d[0];
  spec.spacingY = d[1];
}

LuminaireModel readModel(const Reader& reader, const Field& field) {
  const std::string model = reader.text(field);
  if (model == "point") return LuminaireModel::Point;
  if (model == "area") return LuminaireModel::Area;
  reader.fail(field.where,
              "unknown model '" + model + "'; a luminaire's model is 'point' or 'area'");
}

}  // namespace

LuminaireSpec readLuminaire(const Reader& reader, const Field& field) {
  const MapView map = reader.map(field, "a luminaire");
  map.allowOnly(
      {"name", "file", "position", "aim", "array", "flux_lm", "maintenance_factor", "model"},
      "a luminaire");
  LuminaireSpec spec;
  spec.where = field.where;
  spec.name = reader.text(map.require("name"));
  const Field file = map.require("file");
  spec.file = reader.text(file);
  spec.fileWhere = file.where;
  spec.position = reader.vec3(map.require("position"));
  if (const std::optional<Field> aim = map.find("aim")) spec.aim = readAim(reader, *aim);
  if (const std::optional<Field> array = map.find("array")) readArray(reader, *array, spec);
  if (const std::optional<Field> flux = map.find("flux_lm")) {
    spec.fluxLm = reader.positive(*flux, "lm");
    spec.fluxWhere = flux->where;
  }
  if (const std::optional<Field> mf = map.find("maintenance_factor")) {
    spec.maintenanceFactor = reader.number(*mf);
    if (!(spec.maintenanceFactor > 0.0 && spec.maintenanceFactor <= 1.0)) {
      reader.fail(mf->where, "a maintenance factor lies in (0, 1], got " +
                                 formatNumber(spec.maintenanceFactor));
    }
  }
  if (const std::optional<Field> model = map.find("model")) {
    spec.model = readModel(reader, *model);
    spec.modelWhere = model->where;
  }
  return spec;
}

}  // namespace penumbra::scenefile
