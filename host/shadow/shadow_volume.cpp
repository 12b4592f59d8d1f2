#include "shadow/shadow_volume.hpp"

#include <algorithm>
#include <limits>
#include <utility>

namespace penumbra {

namespace {

// What the construction needs of a convex set: vertices, edges as vertex pairs, outward face
// normals. An area source is a flat set whose two "faces" are its plane, both ways.
struct ConvexSet {
  std::vector<Vec3> vertices;
  std::vector<std::pair<int, int>> edges;
  std::vector<Vec3> faceNormals;
};

ConvexSet convexSet(const ConvexPolygon& polygon) {
  ConvexSet set;
  set.vertices = polygon.vertices();
  const int m = polygon.size();
  for (int i = 0; i < m; ++i) set.edges.emplace_back(i, (i + 1) % m);
  set.faceNormals = {polygon.normal(), -polygon.normal()};
  return set;
}

ConvexSet convexSet(const ConvexPolyhedron& polyhedron) {
  ConvexSet set;
  set.vertices = polyhedron.vertices();
  for (const auto& e : polyhedron.edges()) set.edges.emplace_back(e.from, e.to);
  for (const auto& f : polyhedron.faces()) set.faceNormals.push_back(f.plane.normal);
  return set;
}

// The unit normal of the plane through a and the directions u, v; none when they are (nearly)
// parallel, relative to their lengths, so that no plane is built from rounding noise.
bool planeNormal(const Vec3& u, const Vec3& v, Vec3& normal) {
  const Vec3 n = u.cross(v);
  const double scale = u.norm() * v.norm();
  if (!(n.norm() > Tolerance::kRelativeGeometry * scale)) return false;
  normal = n.normalized();
  return true;
}

class PenumbraPlanes {
 public:
  // The generators x − s (occluder vertex minus source vertex) and their leak bounds, once:
  // every candidate normal is tested against all of them.
  PenumbraPlanes(const ConvexSet& source, const ConvexSet& occluder, const Tolerance& tolerance)
      : source_(source), occluder_(occluder) {
    for (const Vec3& x : occluder_.vertices)
      for (const Vec3& s : source_.vertices) {
        const Vec3 d = x - s;
        const double length = d.norm();
        if (length <= tolerance.length) continue;
        generators_.push_back(d);
        leaks_.push_back(Tolerance::kRelativeGeometry * length);
      }
  }

  // Keeps n·P <= max over the occluder of n·x when that half-space holds V + cone(V − S): every
  // generator x − s must satisfy n·(x − s) <= 0. Pairs closer than the length tolerance are one
  // point (an occluder touching the source), and give no direction. Otherwise the test is
  // relative to the generator's length, so that a plane is never accepted whose leak along a
  // generator exceeds kRelativeGeometry per metre travelled.
  void tryNormal(const Vec3& n) {
    for (std::size_t g = 0; g < generators_.size(); ++g)
      if (n.dot(generators_[g]) > leaks_[g]) return;
    double offset = -std::numeric_limits<double>::infinity();
    for (const Vec3& x : occluder_.vertices) offset = std::max(offset, n.dot(x));
    planes_.push_back(Plane{n, offset});
  }

  void tryBothWays(const Vec3& n) {
    tryNormal(n);
    tryNormal(-n);
  }

  std::vector<Plane> build() {
    // Ŝ: a source vertex and an occluder edge.
    for (const Vec3& q : source_.vertices)
      for (const auto& [i, j] : occluder_.edges) {
        const Vec3& a = occluder_.vertices[i];
        Vec3 n;
        if (planeNormal(occluder_.vertices[j] - a, q - a, n)) tryBothWays(n);
      }
    // S̄: an occluder vertex and a source edge.
    for (const Vec3& v : occluder_.vertices)
      for (const auto& [i, j] : source_.edges) {
        const Vec3& a = source_.vertices[i];
        Vec3 n;
        if (planeNormal(source_.vertices[j] - a, v - a, n)) tryBothWays(n);
      }
    // S: the occluder's own faces (kept when the source is on their outer side: class A), and
    // the source's faces (a facet only where the occluder touches them).
    for (const Vec3& n : occluder_.faceNormals) tryNormal(n);
    for (const Vec3& n : source_.faceNormals) tryBothWays(n);
    return std::move(planes_);
  }

 private:
  const ConvexSet& source_;
  const ConvexSet& occluder_;
  std::vector<Vec3> generators_;
  std::vector<double> leaks_;
  std::vector<Plane> planes_;
};

double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double t = std::clamp(d.dot(p - a) / std::max(d.squaredNorm(), 1e-300), 0.0, 1.0);
  return (a + t * d - p).norm();
}

// The planes of the shadow volume of one source vertex q: V + cone(V − q) (Nishita §2.3): the
// occluder's faces that have q on their outer side or on them, and the planes through q and
// every contour edge of V seen from q. Borderline faces and edges are all kept: an extra plane
// only shrinks the umbra. An edge through q itself (q a vertex or on an edge of V, as a window
// corner on its reveal) needs no plane: the faces through q bound the cone there. False when a
// needed plane is undefined (q on the extension of a contour edge): then no umbra is claimed.
bool vertexShadowPlanes(const Vec3& q, const ConvexPolyhedron& occluder, double tolerance,
                        std::vector<Plane>& planes) {
  const auto& faces = occluder.faces();
  std::vector<double> distance(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f) {
    distance[f] = faces[f].plane.signedDistance(q);
    if (distance[f] >= -tolerance) planes.push_back(faces[f].plane);
  }
  for (const auto& e : occluder.edges()) {
    const double l = distance[e.left], r = distance[e.right];
    const bool contour = (l >= -tolerance && r <= tolerance) || (l <= tolerance && r >= -tolerance);
    if (!contour) continue;
    const Vec3& a = occluder.vertices()[e.from];
    const Vec3& b = occluder.vertices()[e.to];
    Vec3 n;
    if (!planeNormal(b - a, q - a, n)) {
      if (distanceToSegment(q, a, b) <= tolerance) continue;
      return false;
    }
    // A supporting plane along the edge has its normal between the two faces' outward normals.
    const Vec3 outward = faces[e.left].plane.normal + faces[e.right].plane.normal;
    if (n.dot(outward) < 0.0) n = -n;
    planes.push_back(Plane{n, n.dot(a)});
  }
  return true;
}

// Drops planes that repeat another (same normal, offsets within tolerance), keeping the offset
// that errs on the safe side: the larger for a volume that must not shrink, the smaller for one
// that must not grow.
std::vector<Plane> withoutRepeats(std::vector<Plane> planes, double tolerance, bool keepLarger) {
  std::vector<Plane> kept;
  for (const Plane& p : planes) {
    auto same = std::find_if(kept.begin(), kept.end(), [&](const Plane& k) {
      return (k.normal - p.normal).norm() <= Tolerance::kRelativeGeometry &&
             std::abs(k.offset - p.offset) <= tolerance;
    });
    if (same == kept.end()) {
      kept.push_back(p);
    } else if ((p.offset > same->offset) == keepLarger) {
      same->offset = p.offset;
    }
  }
  return kept;
}

ShadowVolume build(const ConvexSet& source, const ConvexPolyhedron& occluder,
                   const Tolerance& tolerance) {
  ShadowVolume volume;
  if (occluder.empty()) return volume;
  const ConvexSet blocker = convexSet(occluder);
  volume.penumbra = withoutRepeats(PenumbraPlanes(source, blocker, tolerance).build(),
                                   tolerance.length, /*keepLarger=*/true);
  std::vector<Plane> umbra;
  for (const Vec3& q : source.vertices)
    if (!vertexShadowPlanes(q, occluder, tolerance.length, umbra)) return volume;
  volume.umbra = withoutRepeats(std::move(umbra), tolerance.length, /*keepLarger=*/false);
  return volume;
}

}  // namespace

bool ShadowVolume::mayShade(const Vec3& p, double margin) const {
  return std::all_of(penumbra.begin(), penumbra.end(),
                     [&](const Plane& plane) { return plane.signedDistance(p) <= margin; });
}

bool ShadowVolume::hides(const Vec3& p, double margin) const {
  return !umbra.empty() && std::all_of(umbra.begin(), umbra.end(), [&](const Plane& plane) {
    return plane.signedDistance(p) < -margin;
  });
}

ShadowVolume shadowVolume(const ConvexPolygon& source, const ConvexPolyhedron& occluder,
                          const Tolerance& tolerance) {
  return build(convexSet(source), occluder, tolerance);
}

ShadowVolume shadowVolume(const ConvexPolyhedron& source, const ConvexPolyhedron& occluder,
                          const Tolerance& tolerance) {
  return build(convexSet(source), occluder, tolerance);
}

}  // namespace penumbra
