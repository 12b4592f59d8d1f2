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

// Some vertex of `other` strictly in front of `plane`.
bool anyInFront(const Plane& plane, const ConvexPolygon& other, double tolerance) {
  return std::any_of(other.vertices().begin(), other.vertices().end(),
                     [&](const Vec3& v) { return plane.signedDistance(v) > tolerance; });
}

}  // namespace

bool canExchange(const ConvexPolygon& a, const ConvexPolygon& b, double tolerance) {
  return anyInFront(a.plane(), b, tolerance) && anyInFront(b.plane(), a, tolerance);
}

bool canExchange(const PlanePolygon& a, const PlanePolygon& b, double tolerance) {
  return anyInFront(a.plane, b.polygon, tolerance) && anyInFront(b.plane, a.polygon, tolerance);
}

namespace {

// The cells of a convex piece: nu × nw equal divisions of its extent along u (its longest
// edge's direction) and w, the cell (i, j) the piece clipped to [i, i + 1) × [j, j + 1).
struct CellGrid {
  Vec3 u, w;
  double u0 = 0.0, u1 = 0.0, w0 = 0.0, w1 = 0.0;
  int nu = 1, nw = 1;

  CellGrid(const ConvexPolygon& piece, double size) {
    const std::vector<Vec3>& v = piece.vertices();
    u = Vec3::Zero();
    for (int i = 0; i < piece.size(); ++i) {
      const Vec3 edge = v[(i + 1) % piece.size()] - v[i];
      if (edge.norm() > u.norm()) u = edge;
    }
    u.normalize();
    w = piece.normal().cross(u).normalized();
    u0 = INFINITY, u1 = -INFINITY, w0 = INFINITY, w1 = -INFINITY;
    for (const Vec3& p : v) {
      u0 = std::min(u0, p.dot(u)), u1 = std::max(u1, p.dot(u));
      w0 = std::min(w0, p.dot(w)), w1 = std::max(w1, p.dot(w));
    }
    nu = std::max(1, static_cast<int>(std::ceil((u1 - u0) / size - 1e-9)));
    nw = std::max(1, static_cast<int>(std::ceil((w1 - w0) / size - 1e-9)));
  }

  // `polygon` clipped to the rows [i0, i1) along u (the grid's own planes, so that a range's
  // piece holds the cells within it).
  ConvexPolygon alongU(ConvexPolygon polygon, int i0, int i1, double tolerance) const {
    if (i0 > 0)
      polygon = polygon.clipped(Plane{-u, -(u0 + (u1 - u0) * double(i0) / nu)}, tolerance);
    if (i1 < nu) polygon = polygon.clipped(Plane{u, u0 + (u1 - u0) * double(i1) / nu}, tolerance);
    return polygon;
  }
  // The same for the columns [j0, j1) along w.
  ConvexPolygon alongW(ConvexPolygon polygon, int j0, int j1, double tolerance) const {
    if (j0 > 0)
      polygon = polygon.clipped(Plane{-w, -(w0 + (w1 - w0) * double(j0) / nw)}, tolerance);
    if (j1 < nw) polygon = polygon.clipped(Plane{w, w0 + (w1 - w0) * double(j1) / nw}, tolerance);
    return polygon;
  }
};

// The cells of `piece` at `size` (as cutIntoCells), each with the block of `group` × `group`
// cells that holds it: blocks[k] is that block's polygon, block[c] cell c's.
struct CellsInBlocks {
  std::vector<ConvexPolygon> cells, blocks;
  std::vector<int> block;
};

CellsInBlocks cutIntoBlocks(const ConvexPolygon& piece, double size, int group, double tolerance) {
  const CellGrid grid(piece, size);
  CellsInBlocks out;
  const int blocksAlongW = (grid.nw + group - 1) / group;
  std::vector<int> blockAt;  // per block (along u, along w): index into out.blocks, -1 none yet
  for (int i = 0; i < grid.nu; ++i) {
    if (i % group == 0) blockAt.assign(static_cast<std::size_t>(blocksAlongW), -1);
    const ConvexPolygon strip = grid.alongU(piece, i, i + 1, tolerance);
    for (int j = 0; j < grid.nw && !strip.empty(); ++j) {
      ConvexPolygon cell = grid.alongW(strip, j, j + 1, tolerance);
      if (cell.empty() || !(cell.area() > tolerance * size)) continue;
      int& b = blockAt[static_cast<std::size_t>(j / group)];
      if (b < 0) {
        const int i0 = i / group * group, j0 = j / group * group;
        b = static_cast<int>(out.blocks.size());
        out.blocks.push_back(
            grid.alongW(grid.alongU(piece, i0, std::min(i0 + group, grid.nu), tolerance), j0,
                        std::min(j0 + group, grid.nw), tolerance));
      }
      out.cells.push_back(std::move(cell));
      out.block.push_back(b);
    }
  }
  return out;
}

}  // namespace

std::vector<ConvexPolygon> cutIntoCells(const ConvexPolygon& piece, double size, double tolerance) {
  return cutIntoBlocks(piece, size, 1, tolerance).cells;
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
  refined.casterBlocks = mesh.casterBlocks;  // a cell lies in its element, so in its block
  for (std::size_t i = 0; i < mesh.elements.size(); ++i) {
    const SurfaceElement& element = mesh.elements[i];
    if (!split[i]) {
      refined.elements.push_back(element);
      continue;
    }
    for (ConvexPolygon& cell : halved(element.polygon, tolerance)) {
      const double area = cell.area();
      refined.elements.push_back({std::move(cell), element.solid, element.face, element.reflectance,
                                  area, element.casterBlock});
    }
  }
  placeNodes(refined, order);
  return refined;
}

bool reflectsLight(const Scene& scene, const Solid& solid) {
  return solid.material >= 0 && scene.materials[solid.material].reflectance.maxCoeff() > 0.0;
}

Scene solidsOf(const Scene& scene) {
  Scene solids;
  solids.file = scene.file;
  solids.materials = scene.materials;
  solids.solids = scene.solids;
  solids.room = scene.room;
  return solids;
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
    return reflectsLight(scene, scene.solids[face.solid]);
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
      pieces.push_back({std::move(piece), face.solid, face.face, reflectance, area, -1});
    }
  }
  return pieces;
}

SurfaceMesh buildSurfaceMesh(const Scene& scene, const MeshOptions& options) {
  if (!(options.elementSize > 0.0)) throw std::invalid_argument("element size must be positive");
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  // Cells per block side: blocks of at most casterBlockSize, at least one cell.
  const int group =
      std::max(1, static_cast<int>(std::floor(options.casterBlockSize / options.elementSize)));
  SurfaceMesh mesh;
  for (const SurfacePiece& piece : surfacePieces(scene, mesh.blackSolids)) {
    CellsInBlocks cut = cutIntoBlocks(piece.polygon, options.elementSize, group, tolerance);
    const auto firstBlock = static_cast<int>(mesh.casterBlocks.size());
    for (ConvexPolygon& block : cut.blocks) mesh.casterBlocks.push_back(std::move(block));
    for (std::size_t c = 0; c < cut.cells.size(); ++c) {
      const double area = cut.cells[c].area();
      mesh.elements.push_back({std::move(cut.cells[c]), piece.solid, piece.face, piece.reflectance,
                               area, firstBlock + cut.block[c]});
    }
  }
  placeNodes(mesh, options.quadratureOrder);
  return mesh;
}

}  // namespace penumbra
