#include "study/case_fingerprint.hpp"

#include <fmt/format.h>

#include "geometry/fnv1a_hash.hpp"

namespace penumbra {

std::string caseFingerprint(const Scene& scene, const CaseOutputs& outputs) {
  Fnv1a h;
  h.add(std::string_view("penumbra case 1"));
  h.add(std::string_view(outputs.estimator));
  for (const std::string& name : outputs.files) h.add(std::string_view("output " + name));
  for (const ParameterValue& p : scene.parameters) {
    h.add(std::string_view(p.name));
    h.add(p.value);
  }
  for (const Material& m : scene.materials) {
    h.add(std::string_view(m.name));
    h.add(m.reflectance);
  }
  for (const Solid& solid : scene.solids) {
    h.add(std::string_view(solid.name));
    h.add(static_cast<double>(solid.material));
    for (std::size_t f = 0; f < solid.shape.faces().size(); ++f) {
      h.add(solid.shape.facePolygon(static_cast<int>(f)));
    }
  }
  for (const Source& source : scene.sources) {
    h.add(std::string_view(source.name));
    h.add(source.luminance);
    h.add(source.color);
    for (const ConvexPolygon& face : source.faces) h.add(face);
  }
  // The sky and what it is seen through.
  if (scene.sky) {
    if (scene.sky->model == SkyModel::CieGeneral) {
      h.add(std::string_view("sky cie-general"));
      h.add(static_cast<double>(scene.sky->cieType));
      h.add(static_cast<double>(scene.sky->subdivision));
    } else {
      h.add(std::string_view(scene.sky->model == SkyModel::CieOvercast ? "sky cie-overcast"
                                                                       : "sky uniform"));
    }
    h.add(scene.sky->horizontalIlluminance);
    h.add(scene.sky->groundReflectance);
    for (const Opening& opening : scene.room->openings) {
      h.add(std::string_view("opening " + opening.name));
      h.add(opening.transmittance);
      h.add(opening.outer);
    }
  }
  // The sun by where it is (date, time, site and north give it) and what it gives.
  if (scene.sun) {
    h.add(std::string_view("sun"));
    h.add(scene.sun->direction);
    h.add(scene.sun->directNormalIlluminance);
    h.add(scene.sun->aboveHorizon() ? 1.0 : 0.0);
    if (scene.room)
      for (const Opening& opening : scene.room->openings) {
        h.add(std::string_view("sun through " + opening.name));
        h.add(opening.transmittance);
        h.add(opening.outer);
      }
  }
  // A luminaire by what it emits (its table, so that an edited file counts) and where.
  for (const Luminaire& luminaire : scene.luminaires) {
    h.add(std::string_view("luminaire " + luminaire.name));
    h.add(std::string_view(luminaireModelName(luminaire.model)));
    h.add(luminaire.intensityScale);
    const photometry::LightDistribution& d = *luminaire.distribution;
    for (double a : d.planeAnglesDeg()) h.add(a);
    for (double a : d.inPlaneAnglesDeg()) h.add(a);
    for (std::size_t j = 0; j < d.planeAnglesDeg().size(); ++j)
      for (std::size_t k = 0; k < d.inPlaneAnglesDeg().size(); ++k) h.add(d.candela(j, k));
    for (const LuminaireInstance& instance : luminaire.instances) {
      h.add(instance.position);
      for (int c = 0; c < 3; ++c) h.add(Vec3(instance.toScene.col(c)));
    }
  }
  for (const std::string& name : outputs.grids) {
    for (const CalculationGrid& grid : scene.grids) {
      if (grid.name != name) continue;
      h.add(std::string_view(grid.name));
      h.add(grid.spacing);
      for (std::size_t i = 0; i < grid.size(); ++i) {
        h.add(grid.position(i));
        h.add(grid.normal(i));
      }
    }
  }
  return h.hex();
}

}  // namespace penumbra
