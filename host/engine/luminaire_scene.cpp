#include "engine/luminaire_scene.hpp"

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

}  // namespace

LuminaireKernelScene packLuminaires(const Scene& scene, const Vec3& origin) {
  LuminaireKernelScene packed;
  for (const Luminaire& luminaire : scene.luminaires) {
    const int table = static_cast<int>(packed.tables.size());
    packed.tables.push_back(packTable(luminaire, packed));
    for (const LuminaireInstance& instance : luminaire.instances) {
      PnLuminaire l{};
      l.centre = float4Of(instance.position - origin, 0.0);
      const Mat3 toLocal = instance.toScene.transpose();
      l.toLocal0 = float4Of(toLocal.row(0).transpose(), 0.0);
      l.toLocal1 = float4Of(toLocal.row(1).transpose(), 0.0);
      l.toLocal2 = float4Of(toLocal.row(2).transpose(), 0.0);
      l.table = table;
      packed.luminaires.push_back(l);
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

}  // namespace penumbra
