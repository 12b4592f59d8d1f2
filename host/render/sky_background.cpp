#include "render/sky_background.hpp"

#include <cmath>

#include "geometry/angles.hpp"
#include "illuminance/patch_sky.hpp"
#include "illuminance/sunlight.hpp"

namespace penumbra {
namespace {

// Whether the ray from `eye` along `direction` crosses the convex polygon `hole` (ahead of the
// eye, within its edges).
bool crosses(const ConvexPolygon& hole, const Vec3& eye, const Vec3& direction) {
  const Plane plane = hole.plane();
  const double along = plane.normal.dot(direction);
  if (along == 0.0) return false;
  const double t = -plane.signedDistance(eye) / along;
  if (t <= 0.0) return false;
  const Vec3 p = eye + t * direction;
  const std::vector<Vec3>& v = hole.vertices();
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Vec3& a = v[i];
    const Vec3& b = v[(i + 1) % v.size()];
    if ((b - a).cross(p - a).dot(plane.normal) < 0.0) return false;
  }
  return true;
}

}  // namespace

SkyBackground::SkyBackground(const Scene& scene) {
  if (!scene.sky) return;
  sky_ = *scene.sky;
  room_ = scene.room;
  const Vec3 sun = scene.sun ? scene.sun->direction.normalized() : Vec3(Vec3::UnitZ());
  sunDirection_ = sun;
  if (sky_->model == SkyModel::CieGeneral) {
    cie_ = &cieSkyParameters(sky_->cieType);
    const PatchSky relative = patchSky(sky_->subdivision, [&](const Vec3& omega) {
      return cieRelativeLuminance(*cie_, omega, sun);
    });
    cieScale_ = sky_->horizontalIlluminance / horizontalIlluminance(relative);
  }
  if (scene.sun && scene.sun->aboveHorizon()) {
    sunLuminance_ = penumbra::sunLuminance(scene.sun->directNormalIlluminance);
    sunCosRadius_ = std::cos(0.5 * kSunDiameterDegrees * kRadiansPerDegree);
  }
}

double SkyBackground::luminance(const Vec3& eye, const Vec3& direction) const {
  if (!sky_) return 0.0;
  return transmittance(eye, direction) * outdoorLuminance(direction);
}

double SkyBackground::transmittance(const Vec3& eye, const Vec3& direction) const {
  double tau = 1.0;
  if (room_)
    for (const Opening& opening : room_->openings)
      if (crosses(opening.outer, eye, direction)) tau *= opening.transmittance;
  return tau;
}

double SkyBackground::outdoorLuminance(const Vec3& direction) const {
  if (sunLuminance_ > 0.0 && direction.dot(sunDirection_) >= sunCosRadius_) return sunLuminance_;
  const double z = direction.z();
  if (z < 0.0) return sky_->groundLuminance();
  switch (sky_->model) {
    case SkyModel::Uniform:
      return sky_->zenithLuminance();
    case SkyModel::CieOvercast:
      return sky_->zenithLuminance() * (1.0 + 2.0 * z) / 3.0;
    case SkyModel::CieGeneral:
      return cieScale_ * cieRelativeLuminance(*cie_, direction, sunDirection_);
  }
  return 0.0;
}

}  // namespace penumbra
