#pragma once
// The interreflected light over the meshed faces as an interpolant of exact final gathers, for
// renders: every element is cut into triangles (a fan from its first vertex), each triangle
// carries the exact gather per RGB channel at its corners and the midpoints of its sides and is
// interpolated quadratically between them. A triangle is kept when the midpoints lie within the
// tolerance of the straight line between its corners and it is small enough (minDepth);
// otherwise it is cut in four at the midpoints and each quarter is decided the same way, down to
// a depth, below which its points are gathered one by one. Values are taken on one element only, so
// nothing is interpolated across a face edge, and a triangle is decided from its own six values
// alone, so the value at a point does not depend on which points were asked for before: the field
// is shared between views and interval settings of a render.
//
// The interreflected light has no hard shadows (every element is a broad source), but at a
// concave corner the neighbouring face is seen edge-on exactly on the corner line and fills half
// the hemisphere just beside it: E jumps there. Nodes on the boundary of their face's elements
// are therefore gathered a small distance inside (kNudgeInKernelTolerances), where E has its
// limit from the inside; triangles there bend steeply and are cut down to the depth, and points
// within a band along that boundary are gathered exactly (FieldOptions::boundaryBand).
// Triangles are decided only where points are asked for, and kept across calls.
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "geometry/sample_point.hpp"
#include "radiosity/surface_mesh.hpp"

namespace penumbra {

// A point on face `face` of solid `solid` (the solid's face numbering, as SurfaceElement).
struct FacePoint {
  Vec3 position = Vec3::Zero();  // m, on the face's plane
  int solid = -1;
  int face = -1;
};

// The exact interreflected E per RGB channel at points, lx (Interreflection::indirectChannels):
// what the field gathers at its nodes.
using FieldGather = std::function<std::vector<Eigen::Vector3d>(std::span<const SamplePoint>)>;

// Whether a point lies inside one of the scene's solids (by more than the length tolerance).
using InsideSolid = std::function<bool(const Vec3&)>;

struct FieldOptions {
  // How far a side's midpoint may lie from the straight line between its corners, per channel,
  // relative to the interreflected E at the midpoint, for a triangle to be kept. That bounds
  // the linear interpolant's error; the field interpolates quadratically through the midpoints,
  // closer still where E is smooth. Relative to the interreflected E, which is smooth and below
  // any pixel's total E whatever direct shadow crosses the triangle, so that the error relative
  // to the total stays below 1e-3 too: the mesh's own accuracy on the total E (docs/method.md).
  double tolerance = 1e-3;
  // No triangle above this depth is kept, whatever its midpoints say: a fan triangle of a 0.5 m
  // element is cut at least to 0.125 m. Occluders between a point and the elements put creases
  // in the interreflected E (where an occluder's edge and an element's edge line up from the
  // point) that the midpoints of a large triangle can miss: on the office a kept 0.25 m triangle
  // whose midpoints were within 3.2e-4 of the line held a pixel 1.7e-3 off.
  int minDepth = 2;
  // Cuts in four below an element's fan triangle: 5 levels take a 0.5 m element's triangles to
  // 1.6 cm. A triangle still uneven there has its points gathered exactly one by one.
  int maxDepth = 5;
  // Points within this distance (m) of the edge of their face's elements are gathered exactly.
  // At a concave corner the neighbouring face fills half the view just beside the edge, so a
  // point there sees the steps between that face's cells (MeshOptions::linearGather) at a scale
  // of its own distance from the corner, finer than the deepest triangles: on the office the
  // field departed by 3.0e-3 and 4.3e-3 at pixels 2 to 32 mm from a corner without the band.
  // Where the field knows the scene's solids (IndirectField's `insideSolid`), the band runs only
  // along the concave edges, where a solid stands on the face: beside a convex edge (a desk's
  // top, a window's reveal) nothing rises in front of the face and the light bends no faster
  // than elsewhere.
  double boundaryBand = 0.04;
};

struct IndirectFieldStats {
  std::size_t nodes = 0;      // points gathered exactly for the field
  std::size_t triangles = 0;  // triangles decided (kept or cut)
  // Points gathered exactly one by one: on no element, or in a triangle still uneven at the
  // depth limit.
  std::size_t pointsGathered = 0;
  double seconds = 0.0;  // in evaluate(), gathers included
};

class IndirectField {
 public:
  // Nodes at a face's boundary are gathered this many kernel length tolerances inside
  // (Tolerance::kernelLength at the scene's size): far enough that the kernel sees the
  // neighbouring face in front of the point, and far below a pixel (80 µm in the office).
  static constexpr double kNudgeInKernelTolerances = 10.0;

  // `mesh` must outlive the field. `sceneSize` (m, Scene::size) sets the length tolerances.
  // `insideSolid`, where given, tells the concave edges of a face from the convex ones
  // (FieldOptions::boundaryBand); without it every edge of a face's elements counts as concave.
  // It is asked only while the field is built.
  IndirectField(const SurfaceMesh& mesh, double sceneSize, FieldGather gather,
                FieldOptions options = {}, const InsideSolid& insideSolid = {});
  ~IndirectField();
  IndirectField(const IndirectField&) = delete;
  IndirectField& operator=(const IndirectField&) = delete;

  // The interreflected E (lx per channel) at each point, 3 values per point into `channels`:
  // interpolated on the element the point lies on, gathering the triangles it needs first;
  // gathered exactly where the point lies on no element (a face without a mesh). The points are
  // located and interpolated in parallel (the field is only read then); the gathers and the
  // decisions on new triangles run between those passes.
  void evaluate(std::span<const FacePoint> points, std::span<float> channels);
  const IndirectFieldStats& stats() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace penumbra
