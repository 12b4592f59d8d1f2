#pragma once
// What a view shows where its ray meets no solid, in a daylight scene: the sky, the ground below
// the horizon and the sun's disk, each at the luminance the scene's light comes from
// (docs/method.md, "Daylight" and "The sun"), times the transmittance of every opening's glazing
// the ray passes through (an opening's outer rectangle, where the glazing is):
//   sky     uniform: E_h/π; cie-overcast: L_z (1 + 2 ω_z)/3; cie-general: the standard's
//           continuous distribution, scaled as its patches are (the patches the illuminance
//           takes are its values at their centres);
//   ground  ρ_g·E_h/π (ω_z < 0);
//   sun     within kSunDiameterDegrees/2 of its direction: the luminance of the polygon that gives
//           E_dn (illuminance/sunlight.hpp), white.
// Without a sky the background is black, as it is for any scene without daylight. The luminance
// is white (cd/m² in each channel).
#include <optional>

#include "geometry/vec.hpp"
#include "scene/cie_general_sky.hpp"
#include "scene/scene.hpp"

namespace penumbra {

class SkyBackground {
 public:
  explicit SkyBackground(const Scene& scene);

  // Whether the background shows anything (a sky).
  bool lit() const { return sky_.has_value(); }
  // cd/m² seen from `eye` along the unit `direction` when the ray meets no solid.
  double luminance(const Vec3& eye, const Vec3& direction) const;

 private:
  // The glazing's transmittance along the ray: the product over the openings it crosses.
  double transmittance(const Vec3& eye, const Vec3& direction) const;
  // Without glazing, from the sky model, the ground or the sun.
  double outdoorLuminance(const Vec3& direction) const;

  std::optional<Sky> sky_;
  std::optional<Room> room_;
  const CieSkyParameters* cie_ = nullptr;  // cie-general only
  double cieScale_ = 0.0;                  // cd/m² per unit of the standard's relative luminance
  Vec3 sunDirection_ = Vec3::UnitZ();      // unit, also the cie-general sky's sun
  double sunLuminance_ = 0.0;              // cd/m²; 0 without a sun above the horizon
  double sunCosRadius_ = 1.0;              // cos of the disk's angular radius
};

}  // namespace penumbra
