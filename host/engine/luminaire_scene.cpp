#include "engine/luminaire_scene.hpp"

#include "reference/opening_illuminance.hpp"

static_assert(sizeof(PnCandelaTable) == 32,
              "PnCandelaTable layout must match kernels/shared_types.h");
static_assert(sizeof(PnLuminaire) == 80, "PnLuminaire layout must match kernels/shared_types.h");
static_assert(sizeof(PnShadowSolid) == 48,
              "PnShadowSolid layout must match kernels/shared_types.h");
static_assert(sizeof(PnLuminaireParams) == 32,
              "PnLuminaireParams layout must match kernels/shared_types.h");

namespace penumbra {
namespace {

cl_float4 float4Of(const Vec3& v, double w) {
  cl_float4 f;
  for (int k = 0; k < 3; ++k) f.s[k] = static_cast<float>(v[k]);
  f.s[3] = static_cast<float>(w);
  return f;
}

int typeCode(photometry::PhotometricType type) {
  switch (type) {
    case photometry::PhotometricType::C:
      return PN_PHOTOMETRIC_C;
    case photometry::PhotometricType::B:
      return PN_PHOTOMETRIC_B;
    case photometry::PhotometricType::A:
      return PN_PHOTOMETRIC_A;
  }
  return PN_PHOTOMETRIC_C;
}

PnCandelaTable packTable(const Luminaire& luminaire, LuminaireKernelScene& packed) {
  const photometry::LightDistribution& d = *luminaire.distribution;
  PnCandelaTable table{};
  table.type = typeCode(d.type());
  table.firstAngle = static_cast<int>(packed.angles.size());
  table.planeCount = static_cast<int>(d.planeAnglesDeg().size());
  table.inPlaneCount = static_cast<int>(d.inPlaneAnglesDeg().size());
  for (double a : d.planeAnglesDeg()) packed.angles.push_back(static_cast<float>(a));
  for (double a : d.inPlaneAnglesDeg()) packed.angles.push_back(static_cast<float>(a));
  table.firstCandela = static_cast<int>(packed.candela.size());
  for (std::size_t j = 0; j < d.planeAnglesDeg().size(); ++j) {
    for (std::size_t k = 0; k < d.inPlaneAnglesDeg().size(); ++k) {
      packed.candela.push_back(static_cast<float>(luminaire.intensityScale * d.candela(j, k)));
    }
  }
  return table;
}

// Whether the area model integrates `luminaire`'s opening exactly (else: the point model, at
// its centre or over the opening's cells).
bool integratesOpening(const Luminaire& luminaire) {
  return luminaire.model == LuminaireModel::Area && luminaire.opening &&
         !luminaire.opening->subdivided();
}

}  // namespace

int placedInstanceCount(const Scene& scene) {
  int count = 0;
  for (const Luminaire& luminaire : scene.luminaires)
    count += static_cast<int>(luminaire.instances.size());
  return count;
}

LuminaireKernelScene packLuminaires(const Scene& scene, const Vec3& origin) {
  LuminaireKernelScene packed;
  int placed = 0;
  for (const Luminaire& luminaire : scene.luminaires) {
    if (integratesOpening(luminaire)) {
      placed += static_cast<int>(luminaire.instances.size());
      continue;
    }
    const int table = static_cast<int>(packed.tables.size());
    packed.tables.push_back(packTable(luminaire, packed));
    // The point model's centre, or the cells of a subdivided opening (reference/
    // luminaire_illuminance.cpp sums the same point sources).
    std::vector<Vec3> centres = {Vec3::Zero()};
    if (luminaire.model == LuminaireModel::Area && luminaire.opening) {
      const LuminaireOpening& opening = *luminaire.opening;
      centres.clear();
      for (int j = 0; j < opening.partsAlongWidth; ++j)
        for (int i = 0; i < opening.partsAlongLength; ++i)
          centres.push_back(opening.partCentre(i, j));
    }
    for (const LuminaireInstance& instance : luminaire.instances) {
      for (const Vec3& local : centres) {
        PnLuminaire l{};
        l.centre = float4Of(instance.position + instance.toScene * local - origin, 0.0);
        const Mat3 toLocal = instance.toScene.transpose();
        l.toLocal0 = float4Of(toLocal.row(0).transpose(), 0.0);
        l.toLocal1 = float4Of(toLocal.row(1).transpose(), 0.0);
        l.toLocal2 = float4Of(toLocal.row(2).transpose(), 0.0);
        l.table = table;
        l.share = static_cast<float>(1.0 / static_cast<double>(centres.size()));
        packed.luminaires.push_back(l);
        packed.instanceOf.push_back(placed);
      }
      ++placed;
    }
  }
  for (int s = 0; s < static_cast<int>(scene.solids.size()); ++s) {
    const ConvexPolyhedron& shape = scene.solids[s].shape;
    if (shape.empty()) continue;
    PnShadowSolid solid{};
    solid.solid = s;
    solid.firstPlane = static_cast<int>(packed.planes.size());
    for (const auto& face : shape.faces()) {
      packed.planes.push_back(
          float4Of(face.plane.normal, face.plane.offset - face.plane.normal.dot(origin)));
    }
    solid.planeCount = static_cast<int>(packed.planes.size()) - solid.firstPlane;
    Vec3 lo = shape.vertices().front(), hi = lo;
    for (const Vec3& v : shape.vertices()) {
      lo = lo.cwiseMin(v);
      hi = hi.cwiseMax(v);
    }
    solid.lo = float4Of(lo - origin, 0.0);
    solid.hi = float4Of(hi - origin, 0.0);
    packed.solids.push_back(solid);
  }
  return packed;
}

OpeningScene openingScene(const Scene& scene) {
  OpeningScene openings;
  openings.scene.file = scene.file;
  openings.scene.materials = scene.materials;
  openings.scene.solids = scene.solids;
  openings.scene.grids = scene.grids;  // the same bounds, so the same kernel tolerance
  int placed = 0;
  for (const Luminaire& luminaire : scene.luminaires) {
    for (const LuminaireInstance& instance : luminaire.instances) {
      if (integratesOpening(luminaire)) {
        Source source;
        source.name = instance.name;
        source.faces.push_back(placedOpening(*luminaire.opening, instance));
        source.luminance = luminaire.intensityScale;
        source.luminanceCoefficients = luminaire.opening->fit.coefficients;
        openings.scene.sources.push_back(std::move(source));
        openings.instanceOf.push_back(placed);
      }
      ++placed;
    }
  }
  return openings;
}

}  // namespace penumbra
