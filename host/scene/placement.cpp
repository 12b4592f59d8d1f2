#include "scene/placement.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace penumbra::scenefile {

BoundingBox roomInterior(const std::optional<Room>& room) {
  BoundingBox box;
  if (room) {
    box.add(Vec3::Zero());
    box.add(room->size);
  }
  return box;
}

bool insideBox(const BoundingBox& box, const Vec3& p, double tolerance) {
  return (p.array() >= box.lo.array() - tolerance).all() &&
         (p.array() <= box.hi.array() + tolerance).all();
}

bool anyInFront(const Plane& plane, const std::vector<Vec3>& points, double tolerance) {
  return std::any_of(points.begin(), points.end(),
                     [&](const Vec3& p) { return plane.signedDistance(p) > tolerance; });
}

int solidHolding(const std::vector<Solid>& solids, const std::vector<Vec3>& points,
                 double tolerance) {
  if (points.empty()) return -1;
  Vec3 mean = Vec3::Zero();
  for (const Vec3& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  for (std::size_t s = 0; s < solids.size(); ++s) {
    const ConvexPolyhedron& shape = solids[s].shape;
    if (!shape.containsStrictly(mean, tolerance)) continue;
    const bool all = std::all_of(points.begin(), points.end(), [&](const Vec3& p) {
      return std::all_of(shape.faces().begin(), shape.faces().end(), [&](const auto& face) {
        return face.plane.signedDistance(p) <= tolerance;
      });
    });
    if (all) return static_cast<int>(s);
  }
  return -1;
}

namespace {

// To 1e-4 (0.1 mm), finer than anyone types: more digits would show the round-off of computed
// corners and normals. Adding 0.0 turns -0 into 0.
std::string rounded(double v) {
  return fmt::format("{}", std::round(v * 1e4) / 1e4 + 0.0);
}

}  // namespace

std::string describeExtent(const std::vector<Vec3>& points) {
  BoundingBox box;
  for (const Vec3& p : points) box.add(p);
  std::string text;
  const char* axes[] = {"x", "y", "z"};
  for (int a = 0; a < 3; ++a) {
    text += std::string(a == 0 ? "" : ", ") + axes[a] + " " + rounded(box.lo[a]);
    if (rounded(box.hi[a]) != rounded(box.lo[a])) text += " to " + rounded(box.hi[a]);
  }
  return text + " m";
}

std::string describeDirection(const Vec3& direction) {
  return fmt::format("[{}, {}, {}]", rounded(direction.x()), rounded(direction.y()),
                     rounded(direction.z()));
}

}  // namespace penumbra::scenefile
