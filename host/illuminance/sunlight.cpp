#include "illuminance/sunlight.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <numbers>

#include "geometry/angles.hpp"
#include "geometry/tolerance.hpp"
#include "illuminance/far_polygon.hpp"

namespace penumbra {
namespace {

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

// Whether some vertex of `polygon` lies in front of the point's tangent plane.
bool abovePlane(const ConvexPolygon& polygon, const SamplePoint& point) {
  for (const Vec3& v : polygon.vertices())
    if (point.normal.dot(v - point.position) > 0.0) return true;
  return false;
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

std::vector<double> sunlight(const Scene& scene, std::span<const SamplePoint> points,
                             std::vector<char>* beam) {
  std::vector<double> e(points.size(), 0.0);
  if (beam) beam->assign(points.size(), 0);
  if (!scene.sun || !scene.sun->aboveHorizon()) return e;
  const Sun& sun = *scene.sun;
  const double luminance = sunLuminance(sun.directNormalIlluminance);
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  const FarPlacement placement = FarPlacement::of(scene);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 16),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i < r.end(); ++i) {
                        const SamplePoint& point = points[i];
                        const ConvexPolygon disk = sunPolygon(point.position, sun.direction,
                                                              placement.distance(point.position));
                        double sum = 0.0;
                        bool inBeam = false;
                        if (scene.room && insideRoom(*scene.room, point.position, tolerance)) {
                          for (const Opening& opening : scene.room->openings) {
                            const ConvexPolygon through =
                                throughHole(disk, point.position, opening.outer);
                            inBeam = inBeam || abovePlane(through, point);
                            sum += opening.transmittance *
                                   visibleProjectedSolidAngle(through, point, scene, tolerance);
                          }
                        } else {
                          inBeam = abovePlane(disk, point);
                          sum = visibleProjectedSolidAngle(disk, point, scene, tolerance);
                          if (scene.room)
                            sum *= tunnelTransmittance(*scene.room, point.position, tolerance);
                        }
                        e[i] = luminance * sum;
                        if (beam) (*beam)[i] = inBeam;
                      }
                    });
  return e;
}

}  // namespace penumbra
