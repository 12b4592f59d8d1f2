// ConvexPolyhedron::hull: a 3-D convex hull in double precision with an absolute tolerance.
//
// Why penumbra has its own hull: Eigen has none, and no package in the project's dependency
// list (Debian 12 packages, docs/building.md) offers one; CGAL and qhull are not on that list. The
// polyhedra here are small (boxes, prisms, faceted primitives, clipped occluders: tens to a few
// thousand points), so a plain quickhull is fast enough and short enough to read.
//
// Three stages, each with one job:
//  1. Near-duplicate points (within the tolerance) are merged, keeping one of each cluster.
//  2. Quickhull over triangles with the exact orientation predicate. Exactness is what keeps it
//     robust: a quickhull that decides "outside" with a tolerance lets small non-convexities
//     in, and a needle triangle next to one tilts far enough to lose points by many times the
//     tolerance (measured: by the size of the object, on points scattered near a cube's faces).
//     With exact signs the triangulation is the exact hull of the points, and every step
//     leaves a closed 2-manifold.
//  3. The tolerance is applied afterwards, where it cannot break the structure: triangles whose
//     vertices lie within it of one plane become one polygonal face (a box is 6 quads, not 12
//     triangles); vertices left on fewer than three faces (on an edge or inside a face) are
//     removed; a result thinner than the tolerance is empty.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

#include "geometry/convex_polyhedron.hpp"
#include "geometry/exact_predicates.hpp"

namespace penumbra {
namespace {

struct Triangle {
  std::array<int, 3> v{};    // point indices, counter-clockwise about the outward normal
  std::array<int, 3> nb{};   // nb[i]: the triangle across the edge v[i] -> v[(i + 1) % 3]
  Plane plane;               // outward
  std::vector<int> outside;  // points strictly above this triangle
  bool alive = true;
};

// (b - a) x (c - a), evaluated from the vertex opposite the longest edge. For a needle (two
// close vertices, one far) the cross product of the two long edges cancels catastrophically:
// its terms are long * long while the result is long * short. The two shorter edges keep the
// relative error near machine precision.
Vec3 triangleNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  if (bc >= ab && bc >= ca) return (b - a).cross(c - a);
  if (ca >= ab) return (c - b).cross(a - b);
  return (a - c).cross(b - c);
}

Plane planeThrough(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = triangleNormal(a, b, c).normalized();
  return Plane{n, n.dot((a + b + c) / 3.0)};
}

// The outward normal of a hull face loop: that of a large triangle of its vertices (the first,
// the farthest from it, the farthest from their line, taken in loop order). A Newell sum over a
// long thin loop cancels like the needle above; a large triangle of a merged face is as good
// a witness of its plane as any, since all its vertices lie within the tolerance of it.
Vec3 loopNormal(const std::vector<Vec3>& loop) {
  size_t far = 0, widest = 0;
  double farDistance = -1.0, width = -1.0;
  for (size_t i = 1; i < loop.size(); ++i) {
    const double d = (loop[i] - loop[0]).squaredNorm();
    if (d > farDistance) {
      farDistance = d;
      far = i;
    }
  }
  const Vec3 axis = (loop[far] - loop[0]).normalized();
  for (size_t i = 1; i < loop.size(); ++i) {
    const Vec3 offset = loop[i] - loop[0];
    const double d = (offset - offset.dot(axis) * axis).squaredNorm();
    if (i != far && d > width) {
      width = d;
      widest = i;
    }
  }
  const Vec3 n = far < widest ? triangleNormal(loop[0], loop[far], loop[widest])
                              : triangleNormal(loop[0], loop[widest], loop[far]);
  return n.normalized();
}

double distanceToLine(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 direction = (b - a).normalized();
  const Vec3 offset = p - a;
  return (offset - offset.dot(direction) * direction).norm();
}

class QuickHull {
 public:
  // `candidates`: the indices of `points` to build from.
  QuickHull(const std::vector<Vec3>& points, std::vector<int> candidates, double tolerance)
      : points_(points), candidates_(std::move(candidates)), tolerance_(tolerance) {}

  // False when the points span no volume (all within tolerance of one plane).
  bool build() {
    std::array<int, 4> simplex{};
    if (!initialSimplex(simplex)) return false;
    for (int i : candidates_) {
      if (std::find(simplex.begin(), simplex.end(), i) != simplex.end()) continue;
      assignOutside(i, {0, 1, 2, 3});
    }
    while (!pending_.empty()) {
      const int t = pending_.back();
      pending_.pop_back();
      if (!triangles_[t].alive || triangles_[t].outside.empty()) continue;
      addEyePoint(t);
      if (triangles_[t].alive && !triangles_[t].outside.empty()) pending_.push_back(t);
    }
    return true;
  }

  std::vector<int> aliveTriangles() const {
    std::vector<int> alive;
    for (int t = 0; t < static_cast<int>(triangles_.size()); ++t) {
      if (triangles_[t].alive) alive.push_back(t);
    }
    return alive;
  }
  const Triangle& triangle(int t) const { return triangles_[t]; }
  int triangleCount() const { return static_cast<int>(triangles_.size()); }

 private:
  // The largest tetrahedron that is cheap to find: the farthest pair of axis extremes, the
  // point farthest from their line, the point farthest from that plane.
  bool initialSimplex(std::array<int, 4>& simplex) {
    if (candidates_.size() < 4) return false;
    std::array<int, 6> extremes{};
    extremes.fill(candidates_[0]);
    for (int i : candidates_) {
      for (int axis = 0; axis < 3; ++axis) {
        if (points_[i][axis] < points_[extremes[2 * axis]][axis]) extremes[2 * axis] = i;
        if (points_[i][axis] > points_[extremes[2 * axis + 1]][axis]) extremes[2 * axis + 1] = i;
      }
    }
    double widest = -1.0;
    for (int i = 0; i < 6; ++i) {
      for (int j = i + 1; j < 6; ++j) {
        const double d = (points_[extremes[i]] - points_[extremes[j]]).norm();
        if (d > widest) {
          widest = d;
          simplex[0] = extremes[i];
          simplex[1] = extremes[j];
        }
      }
    }
    if (widest <= tolerance_) return false;

    double farthest = -1.0;
    for (int i : candidates_) {
      const double d = distanceToLine(points_[i], points_[simplex[0]], points_[simplex[1]]);
      if (d > farthest) {
        farthest = d;
        simplex[2] = i;
      }
    }
    if (farthest <= tolerance_) return false;

    const Plane base = planeThrough(points_[simplex[0]], points_[simplex[1]], points_[simplex[2]]);
    farthest = -1.0;
    for (int i : candidates_) {
      const double d = std::abs(base.signedDistance(points_[i]));
      if (d > farthest) {
        farthest = d;
        simplex[3] = i;
      }
    }
    if (farthest <= tolerance_) return false;

    // Orient the base so that its outward normal points away from the apex.
    int a = simplex[0], b = simplex[1], c = simplex[2];
    const int d = simplex[3];
    if (orientationSign(points_[a], points_[b], points_[c], points_[d]) > 0) std::swap(b, c);
    addTriangle(a, b, c);  // 0
    addTriangle(b, a, d);  // 1: holds the edge b -> a
    addTriangle(c, b, d);  // 2: holds the edge c -> b
    addTriangle(a, c, d);  // 3: holds the edge a -> c
    linkByEdges({0, 1, 2, 3});
    return true;
  }

  int addTriangle(int a, int b, int c) {
    Triangle t;
    t.v = {a, b, c};
    t.nb = {-1, -1, -1};
    t.plane = planeThrough(points_[a], points_[b], points_[c]);
    triangles_.push_back(std::move(t));
    return static_cast<int>(triangles_.size()) - 1;
  }

  void linkByEdges(const std::vector<int>& group) {
    std::map<std::pair<int, int>, int> owner;  // directed edge -> triangle
    for (int t : group) {
      for (int i = 0; i < 3; ++i) owner[{triangles_[t].v[i], triangles_[t].v[(i + 1) % 3]}] = t;
    }
    for (int t : group) {
      for (int i = 0; i < 3; ++i) {
        triangles_[t].nb[i] = owner.at({triangles_[t].v[(i + 1) % 3], triangles_[t].v[i]});
      }
    }
  }

  bool isAbove(int p, const Triangle& t) const {
    return orientationSign(points_[t.v[0]], points_[t.v[1]], points_[t.v[2]], points_[p]) > 0;
  }

  // Files point p under the triangle it is (approximately) farthest above among those it is
  // exactly above; a point above none is inside or on the hull and is dropped for good.
  void assignOutside(int p, const std::vector<int>& triangles) {
    int best = -1;
    double bestDistance = -INFINITY;
    for (int t : triangles) {
      if (!isAbove(p, triangles_[t])) continue;
      const double d = triangles_[t].plane.signedDistance(points_[p]);
      if (d > bestDistance) {
        bestDistance = d;
        best = t;
      }
    }
    if (best < 0) return;
    if (triangles_[best].outside.empty()) pending_.push_back(best);
    triangles_[best].outside.push_back(p);
  }

  struct HorizonEdge {
    int from, to;
    int across;  // the triangle beyond the horizon, which stays
    int slot;    // index of this edge in `across`
  };

  void addEyePoint(int seed) {
    Triangle& seedTriangle = triangles_[seed];
    // The farthest outside point is a vertex of the final hull: inserting it first keeps every
    // intermediate hull's vertices extreme, which is what makes quickhull well behaved.
    auto eyeIt = std::max_element(seedTriangle.outside.begin(), seedTriangle.outside.end(),
                                  [&](int p, int q) {
                                    return seedTriangle.plane.signedDistance(points_[p]) <
                                           seedTriangle.plane.signedDistance(points_[q]);
                                  });
    const int eye = *eyeIt;
    seedTriangle.outside.erase(eyeIt);

    // Triangles the eye sees. With exact signs they form a disk around the seed.
    std::vector<int> visible{seed};
    std::vector<char> isVisible(triangles_.size(), 0);
    isVisible[seed] = 1;
    for (size_t k = 0; k < visible.size(); ++k) {
      for (int neighbour : triangles_[visible[k]].nb) {
        if (!isVisible[neighbour] && isAbove(eye, triangles_[neighbour])) {
          isVisible[neighbour] = 1;
          visible.push_back(neighbour);
        }
      }
    }

    std::vector<HorizonEdge> horizon;
    if (!orderedHorizon(visible, isVisible, horizon)) {
      // Cannot happen with exact signs; should it ever, dropping the eye keeps the
      // triangulation a valid convex surface.
      return;
    }

    const int firstNew = static_cast<int>(triangles_.size());
    const int count = static_cast<int>(horizon.size());
    for (int k = 0; k < count; ++k) addTriangle(horizon[k].from, horizon[k].to, eye);
    for (int k = 0; k < count; ++k) {
      Triangle& t = triangles_[firstNew + k];
      t.nb[0] = horizon[k].across;
      t.nb[1] = firstNew + (k + 1) % count;
      t.nb[2] = firstNew + (k + count - 1) % count;
      triangles_[horizon[k].across].nb[horizon[k].slot] = firstNew + k;
    }

    std::vector<int> newTriangles(count);
    std::iota(newTriangles.begin(), newTriangles.end(), firstNew);
    std::vector<int> orphans;
    for (int t : visible) {
      triangles_[t].alive = false;
      orphans.insert(orphans.end(), triangles_[t].outside.begin(), triangles_[t].outside.end());
      triangles_[t].outside.clear();
    }
    for (int p : orphans) assignOutside(p, newTriangles);
  }

  // The horizon as one loop, each edge oriented as in its visible triangle. False when it is
  // not a single simple loop.
  bool orderedHorizon(const std::vector<int>& visible, const std::vector<char>& isVisible,
                      std::vector<HorizonEdge>& loop) const {
    std::map<int, HorizonEdge> byStart;
    for (int t : visible) {
      for (int i = 0; i < 3; ++i) {
        const int across = triangles_[t].nb[i];
        if (isVisible[across]) continue;
        const int from = triangles_[t].v[i];
        const int to = triangles_[t].v[(i + 1) % 3];
        const auto& nb = triangles_[across].nb;
        const int slot = static_cast<int>(std::find(nb.begin(), nb.end(), t) - nb.begin());
        if (!byStart.emplace(from, HorizonEdge{from, to, across, slot}).second) return false;
      }
    }
    if (byStart.size() < 3) return false;
    loop.clear();
    const int start = byStart.begin()->first;
    int vertex = start;
    do {
      const auto it = byStart.find(vertex);
      if (it == byStart.end()) return false;
      loop.push_back(it->second);
      vertex = it->second.to;
    } while (vertex != start && loop.size() < byStart.size());
    return vertex == start && loop.size() == byStart.size();
  }

  const std::vector<Vec3>& points_;
  std::vector<int> candidates_;
  double tolerance_;
  std::vector<Triangle> triangles_;
  std::vector<int> pending_;  // triangles that may have outside points
};

// Merges coplanar triangles into polygonal faces. Returns the faces as loops of point indices,
// counter-clockwise about the outward normal; empty when the merged loops do not form a closed
// surface (the caller then falls back to the triangles themselves).
std::vector<std::vector<int>> mergeCoplanar(const QuickHull& quickHull,
                                            const std::vector<int>& alive,
                                            const std::vector<Vec3>& points, double tolerance) {
  std::vector<int> local(quickHull.triangleCount(), -1);  // triangle id -> position in `alive`
  for (int k = 0; k < static_cast<int>(alive.size()); ++k) local[alive[k]] = k;

  auto twiceArea = [&](int k) {
    const Triangle& t = quickHull.triangle(alive[k]);
    return (points[t.v[1]] - points[t.v[0]]).cross(points[t.v[2]] - points[t.v[0]]).norm();
  };
  // Large triangles first: their normals are the best conditioned, so they define each face's
  // plane, and slivers join the face they lie in instead of seeding a face of their own.
  std::vector<int> order(alive.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<double> areas(alive.size());
  for (size_t k = 0; k < alive.size(); ++k) areas[k] = twiceArea(static_cast<int>(k));
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return areas[a] > areas[b]; });

  std::vector<int> region(alive.size(), -1);
  std::vector<std::vector<int>> members;
  for (int seed : order) {
    if (region[seed] >= 0) continue;
    const int id = static_cast<int>(members.size());
    const Plane plane = quickHull.triangle(alive[seed]).plane;
    members.push_back({seed});
    region[seed] = id;
    for (size_t m = 0; m < members[id].size(); ++m) {
      for (int neighbourId : quickHull.triangle(alive[members[id][m]]).nb) {
        const int neighbour = local[neighbourId];
        if (region[neighbour] >= 0) continue;
        const Triangle& t = quickHull.triangle(neighbourId);
        const bool coplanar = t.plane.normal.dot(plane.normal) > 0.0 &&
                              std::all_of(t.v.begin(), t.v.end(), [&](int p) {
                                return std::abs(plane.signedDistance(points[p])) <= tolerance;
                              });
        if (!coplanar) continue;
        region[neighbour] = id;
        members[id].push_back(neighbour);
      }
    }
  }

  // Each region's boundary, walked in the triangles' own direction, is the face's loop.
  std::vector<std::vector<int>> loops;
  std::vector<int> next(points.size(), -1);  // boundary successor of a point, per region
  for (size_t id = 0; id < members.size(); ++id) {
    std::vector<int> starts;
    bool simple = true;
    for (int k : members[id]) {
      const Triangle& t = quickHull.triangle(alive[k]);
      for (int i = 0; i < 3; ++i) {
        if (region[local[t.nb[i]]] == static_cast<int>(id)) continue;
        simple = simple && next[t.v[i]] < 0;
        next[t.v[i]] = t.v[(i + 1) % 3];
        starts.push_back(t.v[i]);
      }
    }
    std::vector<int> loop;
    if (simple && starts.size() >= 3) {
      int vertex = starts.front();
      do {
        loop.push_back(vertex);
        vertex = next[vertex];
      } while (vertex >= 0 && vertex != starts.front() && loop.size() < starts.size());
      simple = vertex == starts.front() && loop.size() == starts.size();
    }
    for (int p : starts) next[p] = -1;
    auto convex = [&](const std::vector<int>& indices) {
      std::vector<Vec3> corners;
      for (int p : indices) corners.push_back(points[p]);
      return ConvexPolygon(std::move(corners)).isConvex(tolerance);
    };
    if (simple && (members[id].size() == 1 || convex(loop))) {
      loops.push_back(std::move(loop));
    } else {
      // Membership is decided triangle by triangle, so when points scatter by about the
      // tolerance a region can come out pinched or with a notch (non-convex). Its triangles
      // then stay faces of their own: nearly coplanar, but each one convex and exact.
      for (int k : members[id]) {
        const Triangle& t = quickHull.triangle(alive[k]);
        loops.push_back({t.v[0], t.v[1], t.v[2]});
      }
    }
  }

  // A vertex on fewer than three faces is not a corner: it lies on an edge between two merged
  // faces, and since both loops are convex it is collinear (within the tolerance) in both.
  // Removing it can collapse a sliver face, which lowers its neighbours' counts: repeat until
  // stable.
  std::vector<int> faceCount(points.size());
  for (bool changed = true; changed;) {
    changed = false;
    std::fill(faceCount.begin(), faceCount.end(), 0);
    for (const auto& loop : loops) {
      for (int p : loop) ++faceCount[p];
    }
    for (auto& loop : loops) {
      const auto removed =
          std::remove_if(loop.begin(), loop.end(), [&](int p) { return faceCount[p] < 3; });
      if (removed != loop.end()) {
        loop.erase(removed, loop.end());
        changed = true;
      }
    }
    const auto collapsed = std::remove_if(loops.begin(), loops.end(),
                                          [](const std::vector<int>& l) { return l.size() < 3; });
    if (collapsed != loops.end()) {
      loops.erase(collapsed, loops.end());
      changed = true;
    }
  }

  // The merged loops must still close up: every directed edge once, with its reverse.
  std::vector<std::pair<int, int>> directed;
  for (const auto& loop : loops) {
    for (size_t i = 0; i < loop.size(); ++i) {
      directed.emplace_back(loop[i], loop[(i + 1) % loop.size()]);
    }
  }
  std::sort(directed.begin(), directed.end());
  if (std::adjacent_find(directed.begin(), directed.end()) != directed.end()) return {};
  for (const auto& [from, to] : directed) {
    if (!std::binary_search(directed.begin(), directed.end(), std::pair(to, from))) return {};
  }
  if (loops.size() < 4) return {};
  return loops;
}

// Indices of the points that remain when each point within `tolerance` of an already kept one
// is dropped. Sorting by x limits the comparisons to the points within `tolerance` in x.
std::vector<int> distinctPoints(const std::vector<Vec3>& points, double tolerance) {
  std::vector<int> byX(points.size());
  std::iota(byX.begin(), byX.end(), 0);
  std::stable_sort(byX.begin(), byX.end(),
                   [&](int a, int b) { return points[a].x() < points[b].x(); });
  std::vector<char> dropped(points.size(), 0);
  std::vector<int> kept;
  for (size_t i = 0; i < byX.size(); ++i) {
    if (dropped[byX[i]]) continue;
    const Vec3& p = points[byX[i]];
    for (size_t j = i + 1; j < byX.size() && points[byX[j]].x() - p.x() <= tolerance; ++j) {
      if ((points[byX[j]] - p).norm() <= tolerance) dropped[byX[j]] = 1;
    }
    kept.push_back(byX[i]);
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

}  // namespace

ConvexPolyhedron ConvexPolyhedron::hull(const std::vector<Vec3>& points, double tolerance) {
  QuickHull quickHull(points, distinctPoints(points, tolerance), tolerance);
  if (!quickHull.build()) return {};
  const std::vector<int> alive = quickHull.aliveTriangles();

  std::vector<std::vector<int>> loops = mergeCoplanar(quickHull, alive, points, tolerance);
  if (loops.empty()) {
    for (int t : alive) {
      const Triangle& triangle = quickHull.triangle(t);
      loops.push_back({triangle.v[0], triangle.v[1], triangle.v[2]});
    }
  }

  // Renumber the points that are hull vertices, in input order (deterministic output).
  std::vector<int> used;
  for (const auto& loop : loops) used.insert(used.end(), loop.begin(), loop.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<int> renumber(points.size(), -1);
  std::vector<Vec3> vertices;
  vertices.reserve(used.size());
  for (int p : used) {
    renumber[p] = static_cast<int>(vertices.size());
    vertices.push_back(points[p]);
  }

  std::vector<Face> faces;
  faces.reserve(loops.size());
  for (const auto& loop : loops) {
    Face face;
    std::vector<Vec3> corners;
    for (int p : loop) {
      face.vertices.push_back(renumber[p]);
      corners.push_back(points[p]);
    }
    const Vec3 normal = loopNormal(corners);
    // The offset makes the plane supporting: no vertex outside it. For a long thin face the
    // normal's error is a rotation about the face's long axis, which tilts the plane far from
    // the face; through its own centre that would put distant vertices outside.
    double offset = -INFINITY;
    for (const Vec3& v : vertices) offset = std::max(offset, normal.dot(v));
    face.plane = Plane{normal, offset};
    faces.push_back(std::move(face));
  }

  // The initial tetrahedron only bounds the thickness from one plane's point of view; the
  // depth behind each final face is the width across it.
  for (const Face& face : faces) {
    double depth = 0.0;
    for (const Vec3& v : vertices) depth = std::max(depth, -face.plane.signedDistance(v));
    if (depth <= tolerance) return {};
  }
  return fromFaces(std::move(vertices), std::move(faces));
}

}  // namespace penumbra
