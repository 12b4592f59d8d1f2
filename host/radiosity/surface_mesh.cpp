#include "radiosity/surface_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>

#include "geometry/bounding_box.hpp"
#include "geometry/face_outside_solids.hpp"
#include "geometry/tolerance.hpp"
#include "radiosity/element_quadrature.hpp"

namespace penumbra {

double SurfaceMesh::area() const {
  double a = 0.0;
  for (const SurfaceElement& e : elements) a += e.area;
  return a;
}

namespace {

struct FaceRef {
  int solid = -1, face = -1;
  ConvexPolygon polygon;
};

// Some vertex of `other` strictly in front of `polygon`'s plane.
bool anyInFront(const ConvexPolygon& polygon, const ConvexPolygon& other, double tolerance) {
  const Plane plane = polygon.plane();
  return std::any_of(other.vertices().begin(), other.vertices().end(),
                     [&](const Vec3& v) { return plane.signedDistance(v) > tolerance; });
}

}  // namespace

bool canExchange(const ConvexPolygon& a, const ConvexPolygon& b, double tolerance) {
  return anyInFront(a, b, tolerance) && anyInFront(b, a, tolerance);
}

std::vector<ConvexPolygon> cutIntoCells(const ConvexPolygon& piece, double size, double tolerance) {
  const std::vector<Vec3>& v = piece.vertices();
  Vec3 u = Vec3::Zero();
  for (int i = 0; i < piece.size(); ++i) {
    const Vec3 edge = v[(i + 1) % piece.size()] - v[i];
    if (edge.norm() > u.norm()) u = edge;
  }
  u.normalize();
  const Vec3 w = piece.normal().cross(u).normalized();
  double u0 = INFINITY, u1 = -INFINITY, w0 = INFINITY, w1 = -INFINITY;
  for (const Vec3& p : v) {
    u0 = std::min(u0, p.dot(u)), u1 = std::max(u1, p.dot(u));
    w0 = std::min(w0, p.dot(w)), w1 = std::max(w1, p.dot(w));
  }
  const int nu = std::max(1, static_cast<int>(std::ceil((u1 - u0) / size - 1e-9)));
  const int nw = std::max(1, static_cast<int>(std::ceil((w1 - w0) / size - 1e-9)));
  std::vector<ConvexPolygon> cells;
  for (int i = 0; i < nu; ++i) {
    ConvexPolygon strip = piece;
    if (i > 0) strip = strip.clipped(Plane{-u, -(u0 + (u1 - u0) * double(i) / nu)}, tolerance);
    if (i + 1 < nu) strip = strip.clipped(Plane{u, u0 + (u1 - u0) * double(i + 1) / nu}, tolerance);
    for (int j = 0; j < nw && !strip.empty(); ++j) {
      ConvexPolygon cell = strip;
      if (j > 0) cell = cell.clipped(Plane{-w, -(w0 + (w1 - w0) * double(j) / nw)}, tolerance);
      if (j + 1 < nw) cell = cell.clipped(Plane{w, w0 + (w1 - w0) * double(j + 1) / nw}, tolerance);
      if (!cell.empty() && cell.area() > tolerance * size) cells.push_back(cell);
    }
  }
  return cells;
}

double longestEdge(const ConvexPolygon& polygon) {
  double longest = 0.0;
  const std::vector<Vec3>& v = polygon.vertices();
  for (std::size_t k = 0; k < v.size(); ++k)
    longest = std::max(longest, (v[(k + 1) % v.size()] - v[k]).norm());
  return longest;
}

std::vector<ConvexPolygon> halved(const ConvexPolygon& polygon, double tolerance) {
  return cutIntoCells(polygon, 0.5 * longestEdge(polygon), tolerance);
}

void placeNodes(SurfaceMesh& mesh, int order) {
  mesh.nodes.clear();
  mesh.weights.clear();
  mesh.nodeStart.assign(1, 0);
  for (const SurfaceElement& element : mesh.elements) {
    const Vec3 normal = element.polygon.normal();
    for (const QuadratureNode& node : elementQuadrature(element.polygon, order)) {
      mesh.nodes.push_back(SamplePoint{node.position, normal, element.solid});
      mesh.weights.push_back(node.weight);
    }
    mesh.nodeStart.push_back(mesh.nodes.size());
  }
}

SurfaceMesh refineMesh(const SurfaceMesh& mesh, const std::vector<char>& split, int order,
                       double tolerance) {
  SurfaceMesh refined;
  refined.blackSolids = mesh.blackSolids;
  for (std::size_t i = 0; i < mesh.elements.size(); ++i) {
    const SurfaceElement& element = mesh.elements[i];
    if (!split[i]) {
      refined.elements.push_back(element);
      continue;
    }
    for (ConvexPolygon& cell : halved(element.polygon, tolerance)) {
      const double area = cell.area();
      refined.elements.push_back(
          {std::move(cell), element.solid, element.face, element.reflectance, area});
    }
  }
  placeNodes(refined, order);
  return refined;
}

std::vector<SurfacePiece> surfacePieces(const Scene& scene, std::vector<std::string>& blackSolids) {
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;

  std::vector<FaceRef> faces;
  for (int s = 0; s < static_cast<int>(scene.solids.size()); ++s) {
    const ConvexPolyhedron& shape = scene.solids[s].shape;
    for (int f = 0; f < static_cast<int>(shape.faces().size()); ++f)
      faces.push_back({s, f, shape.facePolygon(f)});
  }
  const auto reflective = [&](const FaceRef& face) {
    const int m = scene.solids[face.solid].material;
    return m >= 0 && scene.materials[m].reflectance.maxCoeff() > 0.0;
  };

  // Reached faces: those that see a source, then those that see a reached reflective face.
  std::vector<char> reached(faces.size(), 0);
  std::deque<std::size_t> queue;
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (const Source& source : scene.sources) {
      for (const ConvexPolygon& emitter : source.faces) {
        if (canExchange(faces[i].polygon, emitter, tolerance)) reached[i] = 1;
      }
    }
    // A luminaire's photometric centre in front of the face.
    const Plane plane = faces[i].polygon.plane();
    for (const Luminaire& luminaire : scene.luminaires) {
      for (const LuminaireInstance& instance : luminaire.instances) {
        if (plane.signedDistance(instance.position) > tolerance) reached[i] = 1;
      }
    }
    if (reached[i]) queue.push_back(i);
  }
  while (!queue.empty()) {
    const std::size_t a = queue.front();
    queue.pop_front();
    if (!reflective(faces[a])) continue;
    for (std::size_t b = 0; b < faces.size(); ++b) {
      if (reached[b] || !canExchange(faces[a].polygon, faces[b].polygon, tolerance)) continue;
      reached[b] = 1;
      queue.push_back(b);
    }
  }

  const auto boxOf = [](const std::vector<Vec3>& points) {
    BoundingBox box;
    for (const Vec3& p : points) box.add(p);
    return box;
  };
  std::vector<BoundingBox> boxes;
  for (const Solid& solid : scene.solids) boxes.push_back(boxOf(solid.shape.vertices()));

  std::vector<SurfacePiece> pieces;
  std::vector<char> namedBlack(scene.solids.size(), 0);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (!reached[i]) continue;
    const FaceRef& face = faces[i];
    if (!reflective(face)) {
      if (scene.solids[face.solid].material < 0 && !namedBlack[face.solid]) {
        namedBlack[face.solid] = 1;
        blackSolids.push_back(scene.solids[face.solid].name);
      }
      continue;
    }
    const BoundingBox faceBox = boxOf(face.polygon.vertices()).grown(tolerance);
    std::vector<const ConvexPolyhedron*> others;
    for (std::size_t s = 0; s < scene.solids.size(); ++s) {
      if (static_cast<int>(s) != face.solid && boxes[s].overlaps(faceBox))
        others.push_back(&scene.solids[s].shape);
    }
    const Vec3 reflectance = scene.materials[scene.solids[face.solid].material].reflectance;
    for (ConvexPolygon& piece : faceOutsideSolids(face.polygon, others, tolerance)) {
      const double area = piece.area();
      pieces.push_back({std::move(piece), face.solid, face.face, reflectance, area});
    }
  }
  return pieces;
}

SurfaceMesh buildSurfaceMesh(const Scene& scene, const MeshOptions& options) {
  if (!(options.elementSize > 0.0)) throw std::invalid_argument("element size must be positive");
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  SurfaceMesh mesh;
  for (const SurfacePiece& piece : surfacePieces(scene, mesh.blackSolids)) {
    for (ConvexPolygon& cell : cutIntoCells(piece.polygon, options.elementSize, tolerance)) {
      const double area = cell.area();
      mesh.elements.push_back({std::move(cell), piece.solid, piece.face, piece.reflectance, area});
    }
  }
  placeNodes(mesh, options.quadratureOrder);
  return mesh;
}

}  // namespace penumbra
