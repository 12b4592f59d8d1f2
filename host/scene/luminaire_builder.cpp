#include "scene/luminaire_builder.hpp"

#include <fmt/format.h>

#include <memory>

#include "photometry/luminous_opening.hpp"
#include "photometry/photometric_error.hpp"
#include "photometry/photometric_file.hpp"

namespace penumbra::scenefile {

std::string instanceName(const std::string& name, int i, int j, bool array) {
  return array ? fmt::format("{}[{},{}]", name, i, j) : name;
}

Luminaire buildLuminaire(const LuminaireSpec& spec, const BuildContext& context) {
  Luminaire luminaire;
  luminaire.name = spec.name;
  luminaire.file = context.file.parent_path() / spec.file;
  photometry::PhotometricData data;
  try {
    data = photometry::readPhotometricFile(luminaire.file);
  } catch (const photometry::PhotometricError& e) {
    context.fail(spec.fileWhere, e.what());
  }
  luminaire.format = data.format;
  luminaire.lightOutputRatio = data.lightOutputRatio;
  luminaire.distribution = std::make_shared<const photometry::LightDistribution>(data);
  luminaire.maintenanceFactor = spec.maintenanceFactor;
  luminaire.model = spec.model.value_or(LuminaireModel::Area);
  luminaire.luminousOutline = photometry::flatOutline(data.opening);
  if (luminaire.model == LuminaireModel::Area) {
    luminaire.opening = luminaireOpening(data.opening, *luminaire.distribution);
    if (!luminaire.opening && !spec.model) {
      luminaire.model = LuminaireModel::Point;  // no flat opening: the default is the point model
    } else if (!luminaire.opening) {
      context.fail(spec.modelWhere,
                   fmt::format("'{}' gives no flat luminous opening (its opening: {}), which the "
                               "area model needs: use 'model: point'",
                               spec.file, photometry::openingShapeName(data.opening.shape)));
    }
  }
  luminaire.lampLumens = data.lampLumens;
  double fluxScale = 1.0;
  if (spec.fluxLm) {
    if (data.absolutePhotometry || data.lampLumens <= 0.0) {
      context.fail(spec.fluxWhere,
                   fmt::format("'{}' has absolute photometry (its table is in cd, with no lamp "
                               "lumens to scale): leave out flux_lm",
                               spec.file));
    }
    fluxScale = *spec.fluxLm / data.lampLumens;
    luminaire.lampLumens = *spec.fluxLm;
  }
  luminaire.intensityScale = fluxScale * spec.maintenanceFactor;

  const Mat3 toScene = aimRotation(spec.aim);
  const bool array = spec.countX * spec.countY > 1;
  for (int j = 0; j < spec.countY; ++j) {
    for (int i = 0; i < spec.countX; ++i) {
      LuminaireInstance instance;
      instance.name = instanceName(spec.name, i + 1, j + 1, array);
      instance.position = spec.position + Vec3(i * spec.spacingX, j * spec.spacingY, 0.0);
      instance.toScene = toScene;
      luminaire.instances.push_back(std::move(instance));
    }
  }
  return luminaire;
}

}  // namespace penumbra::scenefile
