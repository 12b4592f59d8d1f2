#pragma once
// The sky and the ground through the room's openings, exact in double on the host, past every
// solid of the scene: the walls and the reveals of the opening, what stands in the room, and what
// stands outside it (an overhang, fins, a building across the street). Used where the kernel's
// sources cannot hold the obstructions (scene/daylight.hpp, skyOnHost); docs/method.md,
// "Obstructions outside the room".
//
// A receiving point P strictly in front of an opening's outer rectangle O (on the room's side of
// its plane) sees through it the directions of the cone from P over O. That cone, cut where it
// meets the plane parallel to O beyond every solid (far_polygon.hpp, farImage), is a rectangle Q
// with exactly those directions, and every solid lies between P and Q. Q is cut at P's height
// into a sky part (z >= P.z) and a ground part; P receives
//   τ · ( L_z (c_0 M_0 + c_1 M_1) over the sky part   (the sky's polynomial in ω_z, axis +z)
//       + L_g M_0 over the ground part ),
// each moment over the part P sees past the solids, τ the opening's transmittance, the sky's
// luminance as the kernel's sources have it (scene/daylight.hpp). The light does not depend on
// the distance of Q, only on its directions, so this is the kernel's result for a scene without
// obstructions, and the exact one with them. A `cie-general` sky is a sky of patches
// (patch_sky.hpp): each piece of a patch, placed beyond every solid and cut to the directions
// through O (far_polygon.hpp, throughHole), gives L_patch M_0 over the part P sees. The
// obstructions block the sky here; the light they reflect (the externally reflected component)
// is the interreflection's, which lights their faces with surfaceSkylight.
#include <optional>
#include <span>
#include <vector>

#include "geometry/sample_point.hpp"
#include "illuminance/patch_sky.hpp"
#include "scene/scene.hpp"

namespace penumbra {

// E (lx) at every point from the sky and the ground through the openings; zeros when the scene
// has no sky. Whatever skyOnHost says (the Estimator asks it only where it holds).
std::vector<double> skylight(const Scene& scene, std::span<const SamplePoint> points);

// E (lx) from the sky and the ground through the openings, and the ground's part of it: the
// ground seen through the openings, the part of the externally reflected component that does
// not come from the obstructions' faces.
struct SkylightParts {
  std::vector<double> total;   // lx: skylight()'s values, bit for bit
  std::vector<double> ground;  // lx, part of total
};
SkylightParts skylightParts(const Scene& scene, std::span<const SamplePoint> points);

// E (lx) from the sky and the ground on the faces that exchange light (the interreflection's
// nodes): skylight() at points inside the room; at points outside it (scene/daylight.hpp,
// outsideRoom: an obstruction's faces, the room's outer faces) the whole sky and ground in front
// of the point, past every solid, with no glazing. The directions in front of such a point P are
// cut from the six faces of a cube about P beyond every solid (far_polygon.hpp), each cut by P's
// tangent plane and at P's height into a sky and a ground part, integrated as throughOpening
// integrates the far image of an opening.
std::vector<double> surfaceSkylight(const Scene& scene, std::span<const SamplePoint> points);

// The `cie-general` sky `sky` as patches, the sun towards the unit `sunDirection`, scaled so
// that its horizontal illuminance (patch_sky.hpp) is sky.horizontalIlluminance.
PatchSky cieGeneralSky(const Sky& sky, const Vec3& sunDirection);

// skylight() with the sky above the horizon taken from `patches` when given (the scene's sky
// model then only gives the ground), else from the scene's uniform or overcast sky.
std::vector<double> patchSkylight(const Scene& scene, const std::optional<PatchSky>& patches,
                                  std::span<const SamplePoint> points);
// The same with the ground's part.
SkylightParts patchSkylightParts(const Scene& scene, const std::optional<PatchSky>& patches,
                                 std::span<const SamplePoint> points);

}  // namespace penumbra
