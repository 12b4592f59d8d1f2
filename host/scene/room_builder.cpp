#include "scene/room_builder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <fmt/format.h>

namespace penumbra::scenefile {
namespace {

// One wall in its own coordinates: u runs along the wall (x for y-walls, y for x-walls), z up,
// and the slab spans [inner, outer] across it. The y-walls run past the corners (u from -t to
// X + t) and the x-walls fit between them, so that no two slabs overlap.
struct WallFrame {
  std::string id;
  int along = 0;   // axis of u: 0 (x) or 1 (y)
  int across = 1;  // axis through the wall
  double inner = 0.0, outer = 0.0;
  double slabMin = 0.0, slabMax = 0.0;  // u extent of the slab
  double length = 0.0;                  // u extent of the room side: openings lie in [0, length]
  Vec3 inward = Vec3::Zero();           // unit, into the room

  Vec3 point(double u, double z, double a) const {
    Vec3 p;
    p[along] = u;
    p[across] = a;
    p.z() = z;
    return p;
  }
  char alongName() const { return along == 0 ? 'x' : 'y'; }
};

std::array<WallFrame, 4> wallFrames(const RoomSpec& spec) {
  const double x = spec.size.x(), y = spec.size.y(), t = spec.wallThickness;
  return {{
      {"x0", 1, 0, 0.0, -t, 0.0, y, y, Vec3::UnitX()},
      {"x1", 1, 0, x, x + t, 0.0, y, y, -Vec3::UnitX()},
      {"y0", 0, 1, 0.0, -t, -t, x + t, x, Vec3::UnitY()},
      {"y1", 0, 1, y, y + t, -t, x + t, x, -Vec3::UnitY()},
  }};
}

// A rectangle in a wall's (u, z) coordinates.
struct WallRect {
  double u0 = 0.0, u1 = 0.0, z0 = 0.0, z1 = 0.0;
};

struct PlacedOpening {
  const OpeningSpec* spec = nullptr;
  WallRect rect;
};

std::string spanText(const WallFrame& wall, const WallRect& r) {
  return std::string(1, wall.alongName()) + " " + formatNumber(r.u0) + " to " + formatNumber(r.u1) +
         " m, z " + formatNumber(r.z0) + " to " + formatNumber(r.z1) + " m";
}

std::vector<PlacedOpening> placeOpenings(const RoomSpec& spec, const WallFrame& wall,
                                         const BuildContext& context) {
  const double tol = context.tolerance;
  const WallRect inside{0.0, wall.length, 0.0, spec.size.z()};
  std::vector<PlacedOpening> placed;
  for (const OpeningSpec& opening : spec.openings) {
    if (opening.wall != wall.id) continue;
    const WallRect r{opening.along, opening.along + opening.width, opening.sill,
                     opening.sill + opening.height};
    if (r.u0 < inside.u0 - tol || r.u1 > inside.u1 + tol || r.z0 < inside.z0 - tol ||
        r.z1 > inside.z1 + tol) {
      context.fail(opening.where, "opening '" + opening.name + "' does not fit in wall " + wall.id +
                                      ": it spans " + spanText(wall, r) +
                                      ", the wall's room side spans " + spanText(wall, inside));
    }
    for (const PlacedOpening& other : placed) {
      const bool overlapU = std::min(r.u1, other.rect.u1) - std::max(r.u0, other.rect.u0) > tol;
      const bool overlapZ = std::min(r.z1, other.rect.z1) - std::max(r.z0, other.rect.z0) > tol;
      if (overlapU && overlapZ) {
        context.fail(opening.where, "opening '" + opening.name + "' overlaps opening '" +
                                        other.spec->name + "' in wall " + wall.id);
      }
    }
    placed.push_back(PlacedOpening{&opening, r});
  }
  return placed;
}

// The wall's rectangle minus its openings, as non-overlapping rectangles: the wall is cut into
// columns at every opening's side; each column loses the openings spanning it; equal runs of
// neighbouring columns merge (one window gives the classic four pieces: left, right, under the
// sill, over the head).
std::vector<WallRect> wallPieces(const WallFrame& wall, double height,
                                 const std::vector<PlacedOpening>& openings, double tol) {
  std::vector<double> cuts{wall.slabMin, wall.slabMax};
  for (const PlacedOpening& o : openings) {
    cuts.push_back(o.rect.u0);
    cuts.push_back(o.rect.u1);
  }
  std::sort(cuts.begin(), cuts.end());

  std::vector<WallRect> pieces;
  std::vector<std::size_t> open;  // pieces that reach the current column's left side
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    const double a = cuts[c], b = cuts[c + 1];
    if (b - a <= tol) continue;  // two cuts at one place
    const double mid = 0.5 * (a + b);
    std::vector<WallRect> holes;
    for (const PlacedOpening& o : openings) {
      if (o.rect.u0 < mid && mid < o.rect.u1) holes.push_back(o.rect);
    }
    std::sort(holes.begin(), holes.end(),
              [](const WallRect& p, const WallRect& q) { return p.z0 < q.z0; });

    std::vector<std::pair<double, double>> runs;
    double z = 0.0;
    for (const WallRect& h : holes) {
      if (h.z0 - z > tol) runs.emplace_back(z, h.z0);
      z = std::max(z, h.z1);
    }
    if (height - z > tol) runs.emplace_back(z, height);

    std::vector<std::size_t> next;
    for (const auto& run : runs) {
      // Named copies, not a structured binding: clang 14 (fuzz/sanitizer build) cannot capture one.
      const double z0 = run.first, z1 = run.second;
      const auto same = std::find_if(open.begin(), open.end(), [&](std::size_t i) {
        return std::abs(pieces[i].z0 - z0) <= tol && std::abs(pieces[i].z1 - z1) <= tol;
      });
      if (same != open.end()) {
        pieces[*same].u1 = b;
        next.push_back(*same);
      } else {
        pieces.push_back(WallRect{a, b, z0, z1});
        next.push_back(pieces.size() - 1);
      }
    }
    open = std::move(next);
  }
  return pieces;
}

// The opening on the plane across = a, counter-clockwise seen from the room.
ConvexPolygon openingPolygon(const WallFrame& wall, const WallRect& r, double a) {
  const ConvexPolygon polygon({wall.point(r.u0, r.z0, a), wall.point(r.u1, r.z0, a),
                               wall.point(r.u1, r.z1, a), wall.point(r.u0, r.z1, a)});
  return polygon.normal().dot(wall.inward) > 0.0 ? polygon : polygon.reversed();
}

Solid slab(std::string name, const Vec3& a, const Vec3& b, int material) {
  return Solid{std::move(name), ConvexPolyhedron::box(a.cwiseMin(b), a.cwiseMax(b)), material};
}

}  // namespace

BuiltRoom buildRoom(const RoomSpec& spec, const BuildContext& context) {
  BuiltRoom built;
  built.room.size = spec.size;
  built.room.wallThickness = spec.wallThickness;

  const double x = spec.size.x(), y = spec.size.y(), z = spec.size.z(), t = spec.wallThickness;
  built.slabs.push_back(
      slab("room.floor", Vec3(-t, -t, -t), Vec3(x + t, y + t, 0.0), spec.floorMaterial));
  built.slabs.push_back(
      slab("room.ceiling", Vec3(-t, -t, z), Vec3(x + t, y + t, z + t), spec.ceilingMaterial));

  for (const WallFrame& wall : wallFrames(spec)) {
    const std::vector<PlacedOpening> openings = placeOpenings(spec, wall, context);
    const std::vector<WallRect> pieces = wallPieces(wall, z, openings, context.tolerance);
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      const WallRect& p = pieces[i];
      std::string name = "room.wall-" + wall.id;
      if (pieces.size() > 1) name += fmt::format(".{}", i + 1);
      built.slabs.push_back(slab(std::move(name), wall.point(p.u0, p.z0, wall.inner),
                                 wall.point(p.u1, p.z1, wall.outer), spec.wallMaterial));
    }
    for (const PlacedOpening& o : openings) {
      built.room.openings.push_back(Opening{o.spec->name, wall.id, o.spec->transmittance,
                                            openingPolygon(wall, o.rect, wall.inner),
                                            openingPolygon(wall, o.rect, wall.outer)});
    }
  }
  // Openings in file order, whatever wall they are in.
  std::vector<Opening> ordered;
  for (const OpeningSpec& o : spec.openings) {
    for (const Opening& built_opening : built.room.openings) {
      if (built_opening.name == o.name) ordered.push_back(built_opening);
    }
  }
  built.room.openings = std::move(ordered);
  return built;
}

}  // namespace penumbra::scenefile
