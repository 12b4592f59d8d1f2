#include "render/visible_scene.hpp"

#include <stdexcept>

namespace penumbra {
namespace {

void addObject(VisibleScene& visible, int kind, const std::vector<Plane>& planes,
               std::vector<VisibleFace> faces, std::vector<Vec3> vertices,
               std::vector<std::pair<int, int>> edges) {
  PnVisibleObject object{};
  object.firstPlane = static_cast<int>(visible.planes.size());
  object.planeCount = static_cast<int>(planes.size());
  object.firstFaceId = static_cast<int>(visible.faces.size()) + 1;
  object.kind = kind;
  visible.objects.push_back(object);
  visible.planes.insert(visible.planes.end(), planes.begin(), planes.end());
  for (VisibleFace& face : faces) visible.faces.push_back(std::move(face));
  visible.vertices.push_back(std::move(vertices));
  visible.edges.push_back(std::move(edges));
}

std::vector<std::pair<int, int>> polyhedronEdges(const ConvexPolyhedron& shape) {
  std::vector<std::pair<int, int>> edges;
  for (const ConvexPolyhedron::Edge& e : shape.edges()) edges.emplace_back(e.from, e.to);
  return edges;
}

// A polygon source: its plane, then the planes through each edge that contain it, outward.
void addPolygonSource(VisibleScene& visible, int source, const ConvexPolygon& polygon) {
  const Plane plane = polygon.plane();
  std::vector<Plane> planes{plane};
  const std::vector<Vec3>& v = polygon.vertices();
  std::vector<std::pair<int, int>> edges;
  for (int i = 0; i < polygon.size(); ++i) {
    const int j = (i + 1) % polygon.size();
    // Counter-clockwise about the normal: the outside of edge i → j is (v_j − v_i) × n.
    planes.push_back(Plane::through(v[i], (v[j] - v[i]).cross(plane.normal)));
    edges.emplace_back(i, j);
  }
  addObject(visible, PN_VISIBLE_POLYGON, planes, {VisibleFace{true, source, 0, plane}}, v,
            std::move(edges));
}

// A polyhedron source is the intersection of its emitting faces' half-spaces (every face emits
// outwards), with one face id per face.
void addPolyhedronSource(VisibleScene& visible, int source, const Source& s) {
  std::vector<Plane> planes;
  std::vector<VisibleFace> faces;
  std::vector<Vec3> vertices;
  std::vector<std::pair<int, int>> edges;
  for (int f = 0; f < static_cast<int>(s.faces.size()); ++f) {
    const ConvexPolygon& polygon = s.faces[f];
    planes.push_back(polygon.plane());
    faces.push_back(VisibleFace{true, source, f, polygon.plane()});
    const int first = static_cast<int>(vertices.size());
    for (int i = 0; i < polygon.size(); ++i) {
      vertices.push_back(polygon.vertices()[i]);
      edges.emplace_back(first + i, first + (i + 1) % polygon.size());
    }
  }
  addObject(visible, PN_VISIBLE_SOURCE_SOLID, planes, std::move(faces), std::move(vertices),
            std::move(edges));
}

}  // namespace

VisibleScene buildVisibleScene(const Scene& scene) {
  static_assert(sizeof(PnVisibleObject) == 16, "PnVisibleObject layout (shared_types.h)");
  VisibleScene visible;
  for (int s = 0; s < static_cast<int>(scene.solids.size()); ++s) {
    const ConvexPolyhedron& shape = scene.solids[s].shape;
    std::vector<Plane> planes;
    std::vector<VisibleFace> faces;
    for (int f = 0; f < static_cast<int>(shape.faces().size()); ++f) {
      planes.push_back(shape.faces()[f].plane);
      faces.push_back(VisibleFace{false, s, f, shape.faces()[f].plane});
    }
    addObject(visible, PN_VISIBLE_SOLID, planes, std::move(faces), shape.vertices(),
              polyhedronEdges(shape));
  }
  for (int s = 0; s < static_cast<int>(scene.sources.size()); ++s) {
    const Source& source = scene.sources[s];
    if (source.shape == SourceShape::Polygon) {
      addPolygonSource(visible, s, source.faces.front());
    } else {
      addPolyhedronSource(visible, s, source);
    }
  }
  return visible;
}

}  // namespace penumbra
