#include "illuminance/sunlight.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>

#include "geometry/angles.hpp"
#include "geometry/tolerance.hpp"
#include "reference/cosine_moments.hpp"
#include "reference/visible_boundary.hpp"

namespace penumbra {
namespace {

// Lambert's integral ∫ (n·ω) dω over the part of `polygon` that `point` sees past the solids of
// `scene` (sr).
double visibleProjectedSolidAngle(const ConvexPolygon& polygon, const SamplePoint& point,
                                  const Scene& scene, double tolerance) {
  if (polygon.empty() || !(polygon.area() > 0.0)) return 0.0;
  const std::vector<VisibleArc> arcs =
      visibleBoundary(polygon, FaceFrame::of(polygon), point, scene, tolerance);
  if (arcs.empty()) return 0.0;
  const Vec3 n = point.normal.normalized();
  return cosineMoments(arcs, n, n, 0).front();
}

// The part of `sun` (seen from p) whose directions pass through the rectangle `hole`: the
// polygon cut by the plane through p and each edge of the hole.
ConvexPolygon throughHole(const ConvexPolygon& sun, const Vec3& p, const ConvexPolygon& hole) {
  const std::vector<Vec3>& v = hole.vertices();
  const Vec3 inside = hole.centroid() - p;
  ConvexPolygon part = sun;
  for (std::size_t i = 0; i < v.size() && !part.empty(); ++i) {
    Vec3 m = (v[i] - p).cross(v[(i + 1) % v.size()] - p);
    if (m.norm() == 0.0) return {};  // p in the hole's plane: no direction passes through it
    m.normalize();
    if (m.dot(inside) > 0.0) m = -m;  // keep m·(x − p) <= 0, the side of the hole's inside
    part = part.clipped(Plane{m, m.dot(p)}, 0.0);
  }
  return part;
}

// The box of every solid's vertices (empty without solids).
BoundingBox solidBounds(const Scene& scene) {
  BoundingBox box;
  for (const Solid& solid : scene.solids)
    for (const Vec3& v : solid.shape.vertices()) box.add(v);
  return box;
}

bool insideRoom(const Room& room, const Vec3& p, double tolerance) {
  return (p.array() >= -tolerance).all() && (p.array() <= room.size.array() + tolerance).all();
}

// The glazing's transmittance for a point in an opening's tunnel through the wall (on its reveals,
// between the outer and the inner rectangle): the sun reaches it through the outer rectangle,
// where the glazing is. 1 for a point in no tunnel.
double tunnelTransmittance(const Room& room, const Vec3& p, double tolerance) {
  for (const Opening& opening : room.openings) {
    BoundingBox tunnel;
    for (const Vec3& v : opening.inner.vertices()) tunnel.add(v);
    for (const Vec3& v : opening.outer.vertices()) tunnel.add(v);
    if ((p.array() >= tunnel.lo.array() - tolerance).all() &&
        (p.array() <= tunnel.hi.array() + tolerance).all())
      return opening.transmittance;
  }
  return 1.0;
}

}  // namespace

ConvexPolygon sunPolygon(const Vec3& point, const Vec3& direction, double distance) {
  const Vec3 s = direction.normalized();
  const Vec3 centre = point + distance * s;
  const double radius = distance * std::tan(0.5 * kSunDiameterDegrees * kRadiansPerDegree);
  // u × v = −s: counter-clockwise about the normal towards the point.
  const Vec3 u = s.unitOrthogonal();
  const Vec3 v = (-s).cross(u);
  std::vector<Vec3> vertices;
  vertices.reserve(kSunPolygonSides);
  for (int k = 0; k < kSunPolygonSides; ++k) {
    const double phi = 2.0 * std::numbers::pi * k / kSunPolygonSides;
    vertices.push_back(centre + radius * (std::cos(phi) * u + std::sin(phi) * v));
  }
  return ConvexPolygon(std::move(vertices));
}

double sunLuminance(double directNormalIlluminance) {
  // The polygon seen from the origin facing the sun, nothing in the way; the integral does not
  // depend on the direction or the distance (the same directions relative to the normal).
  const Scene empty;
  const SamplePoint facing{Vec3::Zero(), Vec3::UnitZ(), -1};
  const double projected = visibleProjectedSolidAngle(
      sunPolygon(facing.position, Vec3::UnitZ(), 1.0), facing, empty, 0.0);
  return directNormalIlluminance / projected;
}

std::vector<double> sunlight(const Scene& scene, std::span<const SamplePoint> points) {
  std::vector<double> e(points.size(), 0.0);
  if (!scene.sun || !scene.sun->aboveHorizon()) return e;
  const Sun& sun = *scene.sun;
  const double luminance = sunLuminance(sun.directNormalIlluminance);
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  const BoundingBox solids = solidBounds(scene);
  const bool anySolid = (solids.lo.array() <= solids.hi.array()).all();
  const Vec3 centre = anySolid ? Vec3(0.5 * (solids.lo + solids.hi)) : Vec3::Zero();
  const double diagonal = anySolid ? (solids.hi - solids.lo).norm() : 0.0;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, points.size(), 16),
      [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) {
          const SamplePoint& point = points[i];
          // Every solid vertex lies within |P − centre| + diagonal/2 of P: the polygon, at twice
          // that and a metre, lies beyond every solid.
          const double distance = 2.0 * ((point.position - centre).norm() + diagonal) + 1.0;
          const ConvexPolygon disk = sunPolygon(point.position, sun.direction, distance);
          double sum = 0.0;
          if (scene.room && insideRoom(*scene.room, point.position, tolerance)) {
            for (const Opening& opening : scene.room->openings)
              sum += opening.transmittance *
                     visibleProjectedSolidAngle(throughHole(disk, point.position, opening.outer),
                                                point, scene, tolerance);
          } else {
            sum = visibleProjectedSolidAngle(disk, point, scene, tolerance);
            if (scene.room) sum *= tunnelTransmittance(*scene.room, point.position, tolerance);
          }
          e[i] = luminance * sum;
        }
      });
  return e;
}

}  // namespace penumbra
