#include "illuminance/skylight.hpp"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "geometry/tolerance.hpp"
#include "illuminance/far_polygon.hpp"
#include "scene/cie_general_sky.hpp"
#include "scene/daylight.hpp"

namespace penumbra {
namespace {

// What the sky needs at one point: the scene, its tolerance, where far polygons stand, and the
// patches of a sky of patches (null for the uniform and overcast skies).
struct SkyContext {
  const Scene& scene;
  const Sky& sky;
  double tolerance = 0.0;
  FarPlacement placement;
  const PatchSky* patches = nullptr;
};

// E from a sky of patches through `hole` (the opening's outer rectangle): each piece, placed
// beyond every solid, cut to the directions through the hole, integrated past the solids.
double patchIlluminance(const SkyContext& context, const ConvexPolygon& hole,
                        const SamplePoint& point) {
  const Vec3& p = point.position;
  const double distance = context.placement.distance(p);
  double e = 0.0;
  for (const SkyPiece& piece : context.patches->division.pieces) {
    const ConvexPolygon part = throughHole(piecePolygon(piece, p, distance), p, hole);
    if (part.empty()) continue;
    e += context.patches->luminance[static_cast<std::size_t>(piece.patch)] *
         visibleProjectedSolidAngle(part, point, context.scene, context.tolerance);
  }
  return e;
}

// E from the uniform or overcast sky over `skyPart` (a far polygon above P's horizon): the
// luminance polynomial's moments over the part P sees, times L_z.
double skyIlluminance(const SkyContext& context, const ConvexPolygon& skyPart,
                      const SamplePoint& point) {
  const Sky& sky = context.sky;
  if (sky.model == SkyModel::CieOvercast) {
    // L_z (1 + 2 ω_z) / 3.
    const std::vector<double> m =
        visibleMoments(skyPart, point, context.scene, context.tolerance, Vec3::UnitZ(), 1);
    return sky.zenithLuminance() * (m[0] + 2.0 * m[1]) / 3.0;
  }
  return sky.zenithLuminance() *
         visibleProjectedSolidAngle(skyPart, point, context.scene, context.tolerance);
}

// E at `point` through `opening` (before its transmittance), and the ground's part of it.
struct OpeningLight {
  double total = 0.0, ground = 0.0;  // lx
};

OpeningLight throughOpening(const SkyContext& context, const Opening& opening,
                            const SamplePoint& point) {
  const Vec3& p = point.position;
  if (!(opening.outer.plane().signedDistance(p) > context.tolerance)) return {};
  const ConvexPolygon far = farImage(opening.outer, p, context.placement.distance(p));
  const ConvexPolygon skyPart = far.clipped(Plane{-Vec3::UnitZ(), -p.z()}, 0.0);
  const ConvexPolygon groundPart = far.clipped(Plane{Vec3::UnitZ(), p.z()}, 0.0);
  double e = 0.0;
  if (context.patches)
    e += patchIlluminance(context, opening.outer, point);
  else if (!skyPart.empty())
    e += skyIlluminance(context, skyPart, point);
  double ground = 0.0;
  if (!groundPart.empty()) {
    ground = context.sky.groundLuminance() *
             visibleProjectedSolidAngle(groundPart, point, context.scene, context.tolerance);
    e += ground;
  }
  return {e, ground};
}

// The six faces of the cube of half-size `distance` about p, each with its normal towards p.
std::vector<ConvexPolygon> cubeAbout(const Vec3& p, double distance) {
  std::vector<ConvexPolygon> faces;
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {-1.0, 1.0}) {
      const Vec3 a = Vec3::Unit(axis), b = Vec3::Unit((axis + 1) % 3),
                 c = Vec3::Unit((axis + 2) % 3);  // b × c = a
      const Vec3 centre = p + side * distance * a;
      // Counter-clockwise about b × c = a: the normal faces p on the side −1; reversed on +1.
      std::vector<Vec3> v = {centre + distance * (-b - c), centre + distance * (b - c),
                             centre + distance * (b + c), centre + distance * (-b + c)};
      if (side > 0.0) std::reverse(v.begin(), v.end());
      faces.emplace_back(std::move(v));
    }
  return faces;
}

// E at `point` outside the room from the whole sky and ground in front of it (surfaceSkylight).
double openSky(const SkyContext& context, const SamplePoint& point) {
  const Vec3& p = point.position;
  const Vec3 n = point.normal.normalized();
  const Plane front{-n, -n.dot(p)};  // keeps n·(x − p) >= 0
  const double distance = context.placement.distance(p);
  double e = 0.0;
  if (context.patches) {
    for (const SkyPiece& piece : context.patches->division.pieces) {
      const ConvexPolygon part = piecePolygon(piece, p, distance).clipped(front, 0.0);
      if (part.empty()) continue;
      e += context.patches->luminance[static_cast<std::size_t>(piece.patch)] *
           visibleProjectedSolidAngle(part, point, context.scene, context.tolerance);
    }
  }
  for (const ConvexPolygon& face : cubeAbout(p, distance)) {
    const ConvexPolygon seen = face.clipped(front, 0.0);
    if (seen.empty()) continue;
    const ConvexPolygon skyPart = seen.clipped(Plane{-Vec3::UnitZ(), -p.z()}, 0.0);
    const ConvexPolygon groundPart = seen.clipped(Plane{Vec3::UnitZ(), p.z()}, 0.0);
    if (!context.patches && !skyPart.empty()) e += skyIlluminance(context, skyPart, point);
    if (!groundPart.empty())
      e += context.sky.groundLuminance() *
           visibleProjectedSolidAngle(groundPart, point, context.scene, context.tolerance);
  }
  return e;
}

}  // namespace

std::vector<double> surfaceSkylight(const Scene& scene, std::span<const SamplePoint> points) {
  if (!scene.sky || !scene.room) return skylight(scene, points);
  SkyContext context{scene, *scene.sky, Tolerance::forSceneSize(scene.size()).length,
                     FarPlacement::of(scene)};
  // The points inside the room through the openings, together; those outside one by one.
  std::vector<SamplePoint> inside;
  std::vector<std::size_t> insideAt, outsideAt;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const bool outside = outsideRoom(*scene.room, points[i].position, context.tolerance);
    if (!outside) inside.push_back(points[i]);
    (outside ? outsideAt : insideAt).push_back(i);
  }
  std::vector<double> e(points.size(), 0.0);
  const std::vector<double> throughOpenings = skylight(scene, inside);
  for (std::size_t k = 0; k < insideAt.size(); ++k) e[insideAt[k]] = throughOpenings[k];
  std::optional<PatchSky> patches;
  if (scene.sky->model == SkyModel::CieGeneral && !outsideAt.empty()) {
    patches = cieGeneralSky(*scene.sky, scene.sun ? scene.sun->direction : Vec3(Vec3::UnitZ()));
    context.patches = &*patches;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, outsideAt.size(), 8),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k < r.end(); ++k)
                        e[outsideAt[k]] = openSky(context, points[outsideAt[k]]);
                    });
  return e;
}

PatchSky cieGeneralSky(const Sky& sky, const Vec3& sunDirection) {
  const CieSkyParameters& parameters = cieSkyParameters(sky.cieType);
  PatchSky patches = patchSky(sky.subdivision, [&](const Vec3& omega) {
    return cieRelativeLuminance(parameters, omega, sunDirection);
  });
  const double scale = sky.horizontalIlluminance / horizontalIlluminance(patches);
  for (double& l : patches.luminance) l *= scale;
  return patches;
}

std::vector<double> skylight(const Scene& scene, std::span<const SamplePoint> points) {
  return skylightParts(scene, points).total;
}

SkylightParts skylightParts(const Scene& scene, std::span<const SamplePoint> points) {
  if (scene.sky && scene.sky->model == SkyModel::CieGeneral) {
    const PatchSky patches =
        cieGeneralSky(*scene.sky, scene.sun ? scene.sun->direction : Vec3(Vec3::UnitZ()));
    return patchSkylightParts(scene, patches, points);
  }
  return patchSkylightParts(scene, std::nullopt, points);
}

std::vector<double> patchSkylight(const Scene& scene, const std::optional<PatchSky>& patches,
                                  std::span<const SamplePoint> points) {
  return patchSkylightParts(scene, patches, points).total;
}

SkylightParts patchSkylightParts(const Scene& scene, const std::optional<PatchSky>& patches,
                                 std::span<const SamplePoint> points) {
  SkylightParts e{std::vector<double>(points.size(), 0.0), std::vector<double>(points.size(), 0.0)};
  if (!scene.sky) return e;
  SkyContext context{scene, *scene.sky, Tolerance::forSceneSize(scene.size()).length,
                     FarPlacement::of(scene)};
  if (patches) context.patches = &*patches;
  const std::vector<const Opening*> openings = skyOpenings(scene);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 8),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i < r.end(); ++i)
                        for (const Opening* opening : openings) {
                          const OpeningLight light = throughOpening(context, *opening, points[i]);
                          e.total[i] += opening->transmittance * light.total;
                          e.ground[i] += opening->transmittance * light.ground;
                        }
                    });
  return e;
}

}  // namespace penumbra
