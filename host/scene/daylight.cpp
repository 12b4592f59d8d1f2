#include "scene/daylight.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

#include "geometry/tolerance.hpp"

namespace penumbra {

namespace {

bool hasOwnSource(const Scene& scene, const Opening& opening) {
  return std::any_of(scene.sources.begin(), scene.sources.end(),
                     [&](const Source& s) { return s.opening == opening.name; });
}

// A solid that reaches out of the room's outer box (its interior box grown by the wall's
// thickness) by more than `tolerance`: an obstruction outside the room.
bool reachesOutside(const Solid& solid, const Room& room, double tolerance) {
  const double reach = room.wallThickness + tolerance;
  for (const Vec3& v : solid.shape.vertices())
    if ((v.array() < -reach).any() || (v.array() > room.size.array() + reach).any()) return true;
  return false;
}

// The openings whose sky and ground the kernel takes as sources (none when the host does).
std::vector<const Opening*> kernelSkyOpenings(const Scene& scene) {
  if (skyOnHost(scene)) return {};
  return skyOpenings(scene);
}

// The vertical span of a polygon (m).
std::pair<double, double> heightSpan(const ConvexPolygon& polygon) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Vec3& v : polygon.vertices()) {
    lo = std::min(lo, v.z());
    hi = std::max(hi, v.z());
  }
  return {lo, hi};
}

// The part of `face` on the kept side of `boundary` (signed distance <= 0), or nothing when it
// lies within `tolerance` of the cut plane (a sliver along the cut, or a face in that plane).
std::vector<ConvexPolygon> cutPart(const ConvexPolygon& face, const Plane& boundary,
                                   double tolerance) {
  const ConvexPolygon part = face.clipped(boundary, tolerance);
  if (part.empty()) return {};
  const bool onCut =
      std::all_of(part.vertices().begin(), part.vertices().end(),
                  [&](const Vec3& v) { return std::abs(boundary.signedDistance(v)) <= tolerance; });
  if (onCut) return {};
  return {part};
}

// `scene` with a sky and a ground source per opening of `openings`, cut at `height` (m).
Scene withSkySources(const Scene& scene, const std::vector<const Opening*>& openings,
                     double height) {
  Scene lit = scene;
  if (!scene.sky) return lit;
  const Sky& sky = *scene.sky;
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  for (const Opening* opening : openings) {
    Source skySource;
    skySource.name = opening->name + ".sky";
    skySource.faces = cutPart(opening->outer, Plane{-Vec3::UnitZ(), -height}, tolerance);
    skySource.luminance = opening->transmittance * sky.zenithLuminance();
    if (sky.model == SkyModel::CieOvercast) {
      // L_z (1 + 2 ω_z) / 3: the polynomial's scale L_z, its coefficients in ω_z.
      skySource.luminanceCoefficients = {1.0 / 3.0, 2.0 / 3.0};
      skySource.luminanceAxis = Vec3::UnitZ();
    }
    Source ground;
    ground.name = opening->name + ".ground";
    ground.faces = cutPart(opening->outer, Plane{Vec3::UnitZ(), height}, tolerance);
    ground.luminance = opening->transmittance * sky.groundLuminance();
    lit.sources.push_back(std::move(skySource));
    lit.sources.push_back(std::move(ground));
  }
  return lit;
}

}  // namespace

std::vector<const Opening*> skyOpenings(const Scene& scene) {
  std::vector<const Opening*> lit;
  if (!scene.sky || !scene.room) return lit;
  for (const Opening& opening : scene.room->openings)
    if (!hasOwnSource(scene, opening)) lit.push_back(&opening);
  return lit;
}

bool outsideRoom(const Room& room, const Vec3& p, double tolerance) {
  const double reach = room.wallThickness - tolerance;
  return (p.array() <= -reach).any() || (p.array() >= room.size.array() + reach).any();
}

bool solidReachesOutsideRoom(const Scene& scene) {
  if (!scene.room) return false;
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  return std::any_of(scene.solids.begin(), scene.solids.end(), [&](const Solid& solid) {
    return reachesOutside(solid, *scene.room, tolerance);
  });
}

bool skyOnHost(const Scene& scene) {
  if (!scene.sky || !scene.room) return false;
  if (scene.sky->model == SkyModel::CieGeneral) return true;
  return solidReachesOutsideRoom(scene);
}

Scene skyFacesScene(const Scene& scene) {
  const std::vector<const Opening*> openings = skyOpenings(scene);
  Scene faces = withSkySources(scene, openings, scene.bounds().lo.z() - 1.0);
  for (const Opening* opening : openings) {
    std::vector<Vec3> outward(opening->outer.vertices().rbegin(), opening->outer.vertices().rend());
    Source out;
    out.name = opening->name + ".outside";
    out.faces = {ConvexPolygon(std::move(outward))};
    out.luminance = scene.sky->zenithLuminance();
    faces.sources.push_back(std::move(out));
  }
  return faces;
}

double crossingTransmittance(const Scene& scene) {
  const std::vector<const Opening*> openings = skyOpenings(scene);
  if (openings.empty()) return 1.0;
  if (std::all_of(openings.begin(), openings.end(), [&](const Opening* o) {
        return o->transmittance == openings.front()->transmittance;
      }))
    return openings.front()->transmittance;
  double area = 0.0, weighted = 0.0;
  for (const Opening* opening : openings) {
    const double a = opening->outer.area();
    area += a;
    weighted += a * opening->transmittance;
  }
  return area > 0.0 ? weighted / area : 1.0;
}

Scene daylightScene(const Scene& scene, double height) {
  return withSkySources(scene, kernelSkyOpenings(scene), height);
}

std::vector<DaylightGroup> daylightGroups(const Scene& scene, std::span<const SamplePoint> points) {
  std::vector<DaylightGroup> groups;
  const std::vector<const Opening*> openings = kernelSkyOpenings(scene);
  if (openings.empty()) {
    DaylightGroup all;
    for (std::size_t i = 0; i < points.size(); ++i) all.points.push_back(i);
    if (!points.empty()) groups.push_back(std::move(all));
    return groups;
  }
  std::vector<std::pair<double, double>> spans;
  for (const Opening* o : openings) spans.push_back(heightSpan(o->outer));
  // The key: each opening's cut, the height clamped to its span.
  std::map<std::vector<double>, std::size_t> index;
  std::vector<double> key(spans.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double z = points[i].position.z();
    for (std::size_t k = 0; k < spans.size(); ++k)
      key[k] = std::clamp(z, spans[k].first, spans[k].second);
    const auto [it, added] = index.emplace(key, groups.size());
    if (added) groups.push_back(DaylightGroup{z, {}});
    groups[it->second].points.push_back(i);
  }
  return groups;
}

std::vector<SamplePoint> groupPoints(const DaylightGroup& group,
                                     std::span<const SamplePoint> points) {
  std::vector<SamplePoint> out;
  out.reserve(group.points.size());
  for (std::size_t i : group.points) out.push_back(points[i]);
  return out;
}

std::vector<double> estimateByGroup(const Scene& scene, std::span<const SamplePoint> points,
                                    const SceneEstimate& estimate) {
  if (!scene.sky || skyOnHost(scene)) return estimate(daylightScene(scene, 0.0), points);
  std::vector<double> values(points.size(), 0.0);
  for (const DaylightGroup& group : daylightGroups(scene, points)) {
    const std::vector<double> part =
        estimate(daylightScene(scene, group.height), groupPoints(group, points));
    for (std::size_t j = 0; j < part.size(); ++j) values[group.points[j]] = part[j];
  }
  return values;
}

}  // namespace penumbra
