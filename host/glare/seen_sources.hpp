#pragma once
// What an eye sees of each luminous area of a scene, for the glare rating (docs/glare.md): the
// luminance towards the eye and the solid angle of the part of the area the eye sees past the
// solids, in double on the host.
//
// - A Lambertian source (`sources:`) has its luminance L; each face the eye is in front of adds
//   the solid angle of its visible part.
// - A luminaire instance (`luminaires:`) has L = I / A_p: I the file's intensity towards the eye
//   (scaled and maintained as the scene says), A_p = A·cos φ its flat luminous area A projected
//   across the direction to the eye (φ from the opening's normal). Its solid angle is that of the
//   visible part of the opening. A luminaire whose file gives no flat luminous area (a point, a
//   cylinder, a sphere) has no area to see: it is counted, not rated.
//
// The solid angle is exact: the visible region (visible_boundary.hpp: the face minus the shadows
// of the solids on its plane) integrated by regionSolidAngle. The far-field estimate A_p/d² (d to
// the area's centre) is kept beside it for comparison: it ignores occluders and overestimates a
// large area seen from close by.
#include <string>
#include <vector>

#include "geometry/vec.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct SeenSource {
  std::string name;              // the source's, or the luminaire instance's
  double luminance = 0.0;        // cd/m², towards the eye
  double solidAngle = 0.0;       // sr, the visible part
  double farFieldAngle = 0.0;    // sr, A_p/d² over the whole area
  Vec3 toCentre = Vec3::Zero();  // m, from the eye to the luminous area's centre
};

struct EyeView {
  std::vector<SeenSource> sources;  // those the eye sees some of (solid angle > 0)
  int withoutArea = 0;              // luminaire instances without a flat luminous area
};

// Every source and luminaire instance of `scene` as seen from `eye` (m).
EyeView seenSources(const Scene& scene, const Vec3& eye);

}  // namespace penumbra
