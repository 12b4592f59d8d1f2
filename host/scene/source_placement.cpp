#include "scene/source_placement.hpp"

#include <algorithm>
#include <string>

#include <fmt/format.h>

#include "scene/placement.hpp"

namespace penumbra::scenefile {
namespace {

std::vector<Vec3> sourceVertices(const Source& source) {
  std::vector<Vec3> vertices;
  for (const ConvexPolygon& face : source.faces) {
    vertices.insert(vertices.end(), face.vertices().begin(), face.vertices().end());
  }
  return vertices;
}

// Light from `face` can reach the receiver at `p` facing `normal` only when each is in front of
// the other: p in the face's open front half-space, and some vertex of the face in front of the
// receiver's plane.
bool reachesPoint(const ConvexPolygon& face, const Vec3& p, const Vec3& normal, double tolerance) {
  return face.plane().signedDistance(p) > tolerance &&
         anyInFront(Plane::through(p, normal), face.vertices(), tolerance);
}

// The same for a receiving polygon: part of it in front of the face, part of the face in front of
// it.
bool reachesPolygon(const ConvexPolygon& face, const ConvexPolygon& receiver, double tolerance) {
  return anyInFront(face.plane(), receiver.vertices(), tolerance) &&
         anyInFront(receiver.plane(), face.vertices(), tolerance);
}

// Inside the room (or in a scene without one) everything counts. Outside the room the source
// reaches into it only through an opening, so only what is outside the room counts, besides the
// openings; the outside of the room's own slabs is no surface anyone computes.
struct Receivers {
  BoundingBox interior;  // empty: no room, or the source is in it
  double tolerance = 0.0;
  bool counts(const std::vector<Vec3>& points) const {
    return interior.empty() || std::any_of(points.begin(), points.end(), [&](const Vec3& p) {
             return !insideBox(interior, p, tolerance);
           });
  }
};

bool reachesGrid(const ConvexPolygon& face, const CalculationGrid& grid, const Receivers& where) {
  if (grid.kind != GridKind::Points) {
    // The parallelogram lies in front of a plane exactly when one of its corners does.
    const Vec3& o = grid.origin();
    const std::vector<Vec3> corners{o, o + grid.u(), o + grid.u() + grid.v(), o + grid.v()};
    if (!where.counts(corners)) return false;
    return std::any_of(corners.begin(), corners.end(), [&](const Vec3& p) {
      return reachesPoint(face, p, grid.normal(0), where.tolerance);
    });
  }
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const Vec3 p = grid.position(i);
    if (where.counts({p}) && reachesPoint(face, p, grid.normal(i), where.tolerance)) return true;
  }
  return false;
}

bool reachesSolid(const ConvexPolygon& face, const Solid& solid, const Receivers& where) {
  if (!where.interior.empty() && solid.name.starts_with("room.")) return false;
  for (int f = 0; f < static_cast<int>(solid.shape.faces().size()); ++f) {
    const ConvexPolygon receiver = solid.shape.facePolygon(f);
    if (where.counts(receiver.vertices()) && reachesPolygon(face, receiver, where.tolerance))
      return true;
  }
  return false;
}

// From outside the room, through an opening's hole on the room side (it faces into the room).
bool reachesOpening(const ConvexPolygon& face, const Room& room, double tolerance) {
  return std::any_of(room.openings.begin(), room.openings.end(), [&](const Opening& opening) {
    return anyInFront(opening.inner.plane().flipped(), face.vertices(), tolerance) &&
           anyInFront(face.plane(), opening.inner.vertices(), tolerance);
  });
}

bool faceReaches(const ConvexPolygon& face, const Scene& scene, const Receivers& where) {
  if (!where.interior.empty() && reachesOpening(face, *scene.room, where.tolerance)) return true;
  return std::any_of(scene.grids.begin(), scene.grids.end(),
                     [&](const CalculationGrid& g) { return reachesGrid(face, g, where); }) ||
         std::any_of(scene.solids.begin(), scene.solids.end(),
                     [&](const Solid& s) { return reachesSolid(face, s, where); });
}

}  // namespace

void requireSourceOutsideSolids(const Source& source, const Where& where,
                                const std::vector<Solid>& solids, const BuildContext& context) {
  const std::vector<Vec3> vertices = sourceVertices(source);
  const int s = solidHolding(solids, vertices, context.tolerance);
  if (s < 0) return;
  context.fail(where, fmt::format("source '{}' lies inside the solid '{}', where its light never "
                                  "leaves the solid (the source spans {}; the solid {}); move it "
                                  "out, onto the solid's face at most",
                                  source.name, solids[s].name, describeExtent(vertices),
                                  describeExtent(solids[s].shape.vertices())));
}

std::optional<SceneWarning> unlitWarning(const Source& source, const Where& where,
                                         const Scene& scene, double tolerance) {
  const std::vector<Vec3> vertices = sourceVertices(source);
  const BoundingBox room = roomInterior(scene.room);
  const bool inRoom = room.empty() || std::any_of(vertices.begin(), vertices.end(), [&](auto& p) {
                        return insideBox(room, p, tolerance);
                      });
  const Receivers receivers{inRoom ? BoundingBox{} : room, tolerance};
  const bool reaches = std::any_of(source.faces.begin(), source.faces.end(), [&](const auto& face) {
    return faceReaches(face, scene, receivers);
  });
  if (reaches) return std::nullopt;
  std::string why;
  if (!inRoom) {
    why = fmt::format(
        "it lies outside the room ({}; the room's interior spans {}), and no "
        "calculation point, solid or opening of the room is in front of it",
        describeExtent(vertices), describeExtent({room.lo, room.hi}));
  } else if (source.shape == SourceShape::Polygon) {
    why = fmt::format(
        "it emits towards {}, and no calculation point and no face of a solid is "
        "in front of it; check its position and normal",
        describeDirection(source.faces.front().normal()));
  } else {
    why = "no calculation point and no face of a solid is in front of any of its faces";
  }
  return SceneWarning{where.line, where.key,
                      fmt::format("source '{}' lights nothing: {}", source.name, why)};
}

}  // namespace penumbra::scenefile
