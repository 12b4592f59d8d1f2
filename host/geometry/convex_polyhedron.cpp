#include "geometry/convex_polyhedron.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <utility>

#include "geometry/tolerance.hpp"

namespace penumbra {

ConvexPolyhedron ConvexPolyhedron::fromFaces(std::vector<Vec3> vertices, std::vector<Face> faces) {
  ConvexPolyhedron result;
  result.vertices_ = std::move(vertices);
  result.faces_ = std::move(faces);
  // One Edge per undirected edge; the face that first walks it from -> to is its left face.
  std::map<std::pair<int, int>, int> edgeOf;
  for (int f = 0; f < static_cast<int>(result.faces_.size()); ++f) {
    const std::vector<int>& loop = result.faces_[f].vertices;
    for (size_t i = 0; i < loop.size(); ++i) {
      const int from = loop[i];
      const int to = loop[(i + 1) % loop.size()];
      const auto key = std::minmax(from, to);
      const auto [it, inserted] = edgeOf.emplace(std::pair<int, int>(key.first, key.second),
                                                 static_cast<int>(result.edges_.size()));
      if (inserted) {
        result.edges_.push_back(Edge{from, to, f, -1});
        continue;
      }
      Edge& edge = result.edges_[it->second];
      // The factories only build closed, consistently oriented surfaces; anything else is a
      // bug in them, not bad input.
      if (edge.right >= 0 || edge.from != to || edge.to != from) {
        throw std::logic_error("ConvexPolyhedron: faces do not form a closed oriented surface");
      }
      edge.right = f;
    }
  }
  for (const Edge& edge : result.edges_) {
    if (edge.right < 0) {
      throw std::logic_error("ConvexPolyhedron: an edge has only one face");
    }
  }
  return result;
}

ConvexPolyhedron ConvexPolyhedron::box(const Vec3& min, const Vec3& max) {
  if ((max - min).minCoeff() <= 0.0) return {};
  // Vertex i has the max coordinate on axis k when bit k of i is set. Built directly rather
  // than through hull() so that the planes are exactly the axis planes.
  std::vector<Vec3> vertices(8);
  for (int i = 0; i < 8; ++i) {
    vertices[i] =
        Vec3((i & 1) ? max.x() : min.x(), (i & 2) ? max.y() : min.y(), (i & 4) ? max.z() : min.z());
  }
  std::vector<Face> faces = {
      {{0, 4, 6, 2}, Plane{-Vec3::UnitX(), -min.x()}},
      {{1, 3, 7, 5}, Plane{Vec3::UnitX(), max.x()}},
      {{0, 1, 5, 4}, Plane{-Vec3::UnitY(), -min.y()}},
      {{2, 6, 7, 3}, Plane{Vec3::UnitY(), max.y()}},
      {{0, 2, 3, 1}, Plane{-Vec3::UnitZ(), -min.z()}},
      {{4, 5, 7, 6}, Plane{Vec3::UnitZ(), max.z()}},
  };
  return fromFaces(std::move(vertices), std::move(faces));
}

ConvexPolyhedron ConvexPolyhedron::prism(const ConvexPolygon& base, const Vec3& extrusion,
                                         double tolerance) {
  if (base.empty() || std::abs(base.normal().dot(extrusion)) <= tolerance) return {};
  // Through hull(): it orients the caps for either side of the extrusion and merges the side
  // faces of collinear base vertices, which a direct construction would have to redo.
  std::vector<Vec3> points = base.vertices();
  for (const Vec3& v : base.vertices()) points.push_back(v + extrusion);
  return hull(points, tolerance);
}

ConvexPolygon ConvexPolyhedron::facePolygon(int face) const {
  std::vector<Vec3> corners;
  corners.reserve(faces_[face].vertices.size());
  for (int v : faces_[face].vertices) corners.push_back(vertices_[v]);
  return ConvexPolygon(std::move(corners));
}

namespace {

// Calls visit(volume, centroid) for the tetrahedra from an interior reference point to a fan
// triangulation of every face; their volumes are positive for outward counter-clockwise loops.
template <typename Visit>
void forEachTetrahedron(const std::vector<Vec3>& vertices,
                        const std::vector<ConvexPolyhedron::Face>& faces, Visit visit) {
  if (vertices.empty()) return;
  Vec3 reference = Vec3::Zero();
  for (const Vec3& v : vertices) reference += v;
  reference /= static_cast<double>(vertices.size());
  for (const auto& face : faces) {
    const Vec3& a = vertices[face.vertices[0]];
    for (size_t i = 1; i + 1 < face.vertices.size(); ++i) {
      const Vec3& b = vertices[face.vertices[i]];
      const Vec3& c = vertices[face.vertices[i + 1]];
      const double volume = (a - reference).dot((b - reference).cross(c - reference)) / 6.0;
      visit(volume, Vec3((reference + a + b + c) / 4.0));
    }
  }
}

}  // namespace

double ConvexPolyhedron::volume() const {
  double total = 0.0;
  forEachTetrahedron(vertices_, faces_, [&](double v, const Vec3&) { total += v; });
  return total;
}

double ConvexPolyhedron::thickness() const {
  double thinnest = faces_.empty() ? 0.0 : std::numeric_limits<double>::infinity();
  for (const Face& face : faces_) {
    double width = 0.0;
    for (const Vec3& v : vertices_) width = std::max(width, -face.plane.signedDistance(v));
    thinnest = std::min(thinnest, width);
  }
  return thinnest;
}

Vec3 ConvexPolyhedron::centroid() const {
  double total = 0.0;
  Vec3 weighted = Vec3::Zero();
  forEachTetrahedron(vertices_, faces_, [&](double v, const Vec3& c) {
    total += v;
    weighted += v * c;
  });
  return total > 0.0 ? Vec3(weighted / total) : Vec3::Zero();
}

double ConvexPolyhedron::surfaceArea() const {
  double total = 0.0;
  for (int f = 0; f < static_cast<int>(faces_.size()); ++f) total += facePolygon(f).area();
  return total;
}

ConvexPolyhedron ConvexPolyhedron::clipped(const Plane& boundary, double tolerance) const {
  if (empty()) return {};
  std::vector<double> distance(vertices_.size());
  bool allInside = true;
  bool allOutside = true;
  for (size_t i = 0; i < vertices_.size(); ++i) {
    distance[i] = boundary.signedDistance(vertices_[i]);
    allInside = allInside && distance[i] <= tolerance;
    allOutside = allOutside && distance[i] >= -tolerance;
  }
  if (allInside) return *this;
  if (allOutside) return {};

  // The kept part is the hull of the kept vertices and of the points where edges cross the
  // plane. A vertex within tolerance of the plane is kept as it is; crossings are computed only
  // for edges from strictly inside to strictly outside, so they are never within tolerance of
  // an end. hull() merges the new cap into one face and returns empty for a sliver.
  std::vector<Vec3> points;
  for (size_t i = 0; i < vertices_.size(); ++i) {
    if (distance[i] <= tolerance) points.push_back(vertices_[i]);
  }
  for (const Edge& edge : edges_) {
    const double a = distance[edge.from];
    const double b = distance[edge.to];
    if ((a < -tolerance && b > tolerance) || (a > tolerance && b < -tolerance)) {
      const double t = a / (a - b);
      points.push_back(vertices_[edge.from] + t * (vertices_[edge.to] - vertices_[edge.from]));
    }
  }
  return hull(points, tolerance);
}

bool ConvexPolyhedron::containsStrictly(const Vec3& p, double tolerance) const {
  if (empty()) return false;
  return std::all_of(faces_.begin(), faces_.end(),
                     [&](const Face& face) { return face.plane.signedDistance(p) < -tolerance; });
}

int ConvexPolyhedron::faceContaining(const Vec3& p, const Vec3& normal, double tolerance) const {
  int best = -1;
  double bestAlignment = -INFINITY;
  for (int f = 0; f < static_cast<int>(faces_.size()); ++f) {
    if (std::abs(faces_[f].plane.signedDistance(p)) > tolerance) continue;
    const bool insideOthers = std::all_of(faces_.begin(), faces_.end(), [&](const Face& other) {
      return other.plane.signedDistance(p) <= tolerance;
    });
    if (!insideOthers) continue;
    const double alignment = faces_[f].plane.normal.dot(normal);
    if (alignment > bestAlignment) {
      bestAlignment = alignment;
      best = f;
    }
  }
  return best;
}

namespace {

// Chains contour edges (start -> end) into one loop; empty unless they form exactly one
// simple loop.
std::vector<int> chainLoop(const std::map<int, int>& next) {
  if (next.size() < 3) return {};
  std::vector<int> loop;
  const int start = next.begin()->first;
  int vertex = start;
  do {
    const auto it = next.find(vertex);
    if (it == next.end()) return {};
    loop.push_back(vertex);
    vertex = it->second;
  } while (vertex != start && loop.size() < next.size());
  if (vertex != start || loop.size() != next.size()) return {};
  return loop;
}

}  // namespace

std::vector<Vec3> ConvexPolyhedron::silhouette(const Vec3& viewpoint) const {
  if (empty()) return {};
  // silhouette() takes no tolerance, yet "on the boundary" must survive round-off in
  // normal·x - offset: use the geometry tolerance for the size of the coordinates involved.
  double scale = viewpoint.norm();
  for (const Vec3& v : vertices_) scale = std::max(scale, v.norm());
  const double onPlane = Tolerance::forSceneSize(scale).length;

  // Faces that have the viewpoint in their positive space face it ("front"). Their union is a
  // disk whose boundary, walked in the front faces' own (counter-clockwise about the outward
  // normal) direction, is counter-clockwise as seen from the viewpoint.
  auto contour = [&](double threshold) {
    std::vector<char> front(faces_.size());
    bool anyFront = false;
    for (size_t f = 0; f < faces_.size(); ++f) {
      front[f] = faces_[f].plane.signedDistance(viewpoint) > threshold;
      anyFront = anyFront || front[f];
    }
    if (!anyFront) return std::vector<int>{};  // inside or on the boundary
    std::map<int, int> next;
    for (const Edge& edge : edges_) {
      if (front[edge.left] == front[edge.right]) continue;
      const bool ok = front[edge.left] ? next.emplace(edge.from, edge.to).second
                                       : next.emplace(edge.to, edge.from).second;
      if (!ok) return std::vector<int>{};
    }
    return chainLoop(next);
  };

  std::vector<int> loop = contour(onPlane);
  // A face seen almost edge-on can, through round-off, split the front region; classifying by
  // the plain sign then still gives a valid contour of the same outline.
  if (loop.empty() && std::any_of(faces_.begin(), faces_.end(), [&](const Face& face) {
        return face.plane.signedDistance(viewpoint) > onPlane;
      })) {
    loop = contour(0.0);
  }
  std::vector<Vec3> result;
  result.reserve(loop.size());
  for (int v : loop) result.push_back(vertices_[v]);
  return result;
}

}  // namespace penumbra
