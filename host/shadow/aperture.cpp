#include "shadow/aperture.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace penumbra {

namespace {

using Rect = std::array<double, 4>;  // u0, u1, v0, v1

// The coordinate axis a unit vector lies along, or -1.
int axisOf(const Vec3& n) {
  for (int i = 0; i < 3; ++i)
    if (std::abs(n[(i + 1) % 3]) <= Tolerance::kRelativeGeometry &&
        std::abs(n[(i + 2) % 3]) <= Tolerance::kRelativeGeometry)
      return i;
  return -1;
}

// The polygon as a rectangle of the frame, when it is one: four vertices, one at each corner of
// its (u, v) bounding box, all at depth `depth` along `normal`.
bool rectOf(const ConvexPolygon& polygon, const Aperture& frame, const Vec3& normal, double depth,
            double tol, Rect& rect) {
  if (polygon.size() != 4) return false;
  const double inf = std::numeric_limits<double>::infinity();
  rect = {inf, -inf, inf, -inf};
  for (const Vec3& x : polygon.vertices()) {
    if (std::abs(normal.dot(x) - depth) > tol) return false;
    const double u = x.dot(frame.axisU), v = x.dot(frame.axisV);
    rect = {std::min(rect[0], u), std::max(rect[1], u), std::min(rect[2], v), std::max(rect[3], v)};
  }
  if (!(rect[1] - rect[0] > tol && rect[3] - rect[2] > tol)) return false;
  int corners = 0;
  for (const Vec3& x : polygon.vertices()) {
    const double u = x.dot(frame.axisU), v = x.dot(frame.axisV);
    const bool lowU = std::abs(u - rect[0]) <= tol, highU = std::abs(u - rect[1]) <= tol;
    const bool lowV = std::abs(v - rect[2]) <= tol, highV = std::abs(v - rect[3]) <= tol;
    if (!(lowU || highU) || !(lowV || highV)) return false;
    corners |= 1 << ((highU ? 1 : 0) + (highV ? 2 : 0));
  }
  return corners == 15;
}

bool within(const Rect& inner, const Rect& outer, double tol) {
  return inner[0] >= outer[0] - tol && inner[1] <= outer[1] + tol && inner[2] >= outer[2] - tol &&
         inner[3] <= outer[3] + tol;
}

bool holds(const Rect& r, double u, double v, double tol) {
  return u >= r[0] - tol && u <= r[1] + tol && v >= r[2] - tol && v <= r[3] + tol;
}

// A solid that is an axis-aligned box: eight vertices, each a corner of its bounding box.
bool isAxisBox(const ConvexPolyhedron& shape, BoundingBox& box, double tol) {
  if (shape.vertices().size() != 8 || shape.faces().size() != 6) return false;
  box = BoundingBox{};
  for (const Vec3& x : shape.vertices()) box.add(x);
  for (const Vec3& x : shape.vertices())
    for (int i = 0; i < 3; ++i)
      if (std::abs(x[i] - box.lo[i]) > tol && std::abs(x[i] - box.hi[i]) > tol) return false;
  return true;
}

// The room-side face of the wall (the room's box projected along the normal onto A's plane)
// minus the openings in that plane must be covered by box solids that span the wall's whole
// thickness [lo, hi] along the normal axis; the openings must be rectangles apart from one
// another. Decided on the cells between all rectangle sides: each is inside or outside each
// rectangle.
bool wallCovered(const Scene& scene, const Aperture& frame, const Vec3& normal, int axis,
                 double openingDepth, double lo, double hi, const Rect& wallRect, double tol) {
  std::vector<Rect> holes, slabs;
  for (const Opening& o : scene.room->openings) {
    if (std::abs(o.inner.plane().normal.dot(normal)) < 0.5) continue;  // another wall
    if (std::abs(normal.dot(o.inner.vertices()[0]) - openingDepth) > tol) continue;
    Rect r;
    if (!rectOf(o.inner, frame, normal, openingDepth, tol, r)) return false;
    for (const Rect& h : holes)
      if (std::min(r[1], h[1]) - std::max(r[0], h[0]) >= -tol &&
          std::min(r[3], h[3]) - std::max(r[2], h[2]) >= -tol)
        return false;  // touching openings: the wall between them is not there
    holes.push_back(r);
  }
  for (const Solid& solid : scene.solids) {
    BoundingBox box;
    if (!isAxisBox(solid.shape, box, tol)) continue;
    if (box.lo[axis] > lo + tol || box.hi[axis] < hi - tol) continue;
    Rect r{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
           std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
    for (const Vec3& x : solid.shape.vertices()) {
      const double u = x.dot(frame.axisU), v = x.dot(frame.axisV);
      r = {std::min(r[0], u), std::max(r[1], u), std::min(r[2], v), std::max(r[3], v)};
    }
    slabs.push_back(r);
  }
  std::vector<double> us{wallRect[0], wallRect[1]}, vs{wallRect[2], wallRect[3]};
  for (const auto* list : {&holes, &slabs})
    for (const Rect& r : *list) {
      us.insert(us.end(), {std::clamp(r[0], wallRect[0], wallRect[1]),
                           std::clamp(r[1], wallRect[0], wallRect[1])});
      vs.insert(vs.end(), {std::clamp(r[2], wallRect[2], wallRect[3]),
                           std::clamp(r[3], wallRect[2], wallRect[3])});
    }
  std::sort(us.begin(), us.end());
  std::sort(vs.begin(), vs.end());
  us.erase(std::unique(us.begin(), us.end()), us.end());
  vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
  for (std::size_t i = 0; i + 1 < us.size(); ++i)
    for (std::size_t j = 0; j + 1 < vs.size(); ++j) {
      const double u = 0.5 * (us[i] + us[i + 1]), v = 0.5 * (vs[j] + vs[j + 1]);
      const auto inside = [&](const Rect& r) { return holds(r, u, v, tol); };
      if (std::none_of(holes.begin(), holes.end(), inside) &&
          std::none_of(slabs.begin(), slabs.end(), inside))
        return false;
    }
  return true;
}

}  // namespace

std::optional<Aperture> findAperture(const Scene& scene, const ConvexPolygon& face,
                                     const Tolerance& tolerance) {
  if (!scene.room || face.size() != 4) return std::nullopt;
  const double tol = tolerance.length;
  const int axis = axisOf(face.normal());
  if (axis < 0) return std::nullopt;
  const double sign = face.normal()[axis] > 0.0 ? 1.0 : -1.0;
  const Vec3 normal = sign * Vec3::Unit(axis);
  Aperture aperture;
  aperture.axisU = Vec3::Unit((axis + 1) % 3);
  aperture.axisV = sign * Vec3::Unit((axis + 2) % 3);  // axisU × axisV = normal
  const double faceDepth = normal.dot(face.vertices()[0]);
  if (!rectOf(face, aperture, normal, faceDepth, tol, aperture.sourceRect)) return std::nullopt;

  const Room& room = *scene.room;
  aperture.room = BoundingBox{Vec3::Zero(), room.size};
  const Rect wallRect{
      aperture.room.lo.dot(aperture.axisU), aperture.room.hi.dot(aperture.axisU),
      std::min(aperture.room.lo.dot(aperture.axisV), aperture.room.hi.dot(aperture.axisV)),
      std::max(aperture.room.lo.dot(aperture.axisV), aperture.room.hi.dot(aperture.axisV))};
  for (const Opening& opening : room.openings) {
    Rect outer;
    if (!rectOf(opening.outer, aperture, normal, faceDepth, tol, outer)) continue;
    if (!within(aperture.sourceRect, outer, tol)) continue;
    const double openingDepth = normal.dot(opening.inner.vertices()[0]);
    if (!(openingDepth > faceDepth + tol)) return std::nullopt;  // A must be in front
    if (!rectOf(opening.inner, aperture, normal, openingDepth, tol, aperture.openingRect))
      return std::nullopt;
    // P in the room's box and x on the face: the crossing of A's plane is in the wall's rectangle.
    if (!within(aperture.sourceRect, wallRect, tol)) return std::nullopt;
    const double c0 = sign * faceDepth, c1 = sign * openingDepth;  // along the axis
    if (!wallCovered(scene, aperture, normal, axis, openingDepth, std::min(c0, c1),
                     std::max(c0, c1), wallRect, tol))
      return std::nullopt;
    aperture.plane = Plane{normal, openingDepth};
    aperture.sourceDepth = faceDepth;
    return aperture;
  }
  return std::nullopt;
}

bool behindAperture(const Aperture& aperture, const ConvexPolyhedron& occluder,
                    const Tolerance& tolerance) {
  const double tol = tolerance.length;
  if (occluder.empty()) return false;
  const Rect& s = aperture.sourceRect;
  const Rect& a = aperture.openingRect;
  const Rect prism{std::min(s[0], a[0]), std::max(s[1], a[1]), std::min(s[2], a[2]),
                   std::max(s[3], a[3])};
  const double inf = std::numeric_limits<double>::infinity();
  Rect r{inf, -inf, inf, -inf};
  for (const Vec3& x : occluder.vertices()) {
    if (aperture.plane.signedDistance(x) > tol) return false;  // reaches the room side
    const double u = x.dot(aperture.axisU), v = x.dot(aperture.axisV);
    r = {std::min(r[0], u), std::max(r[1], u), std::min(r[2], v), std::max(r[3], v)};
  }
  return r[1] <= prism[0] + tol || r[0] >= prism[1] - tol || r[3] <= prism[2] + tol ||
         r[2] >= prism[3] - tol;
}

}  // namespace penumbra
