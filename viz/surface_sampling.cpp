#include "viz/surface_sampling.hpp"

#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>

#include <Eigen/Core>

#include "geometry/tolerance.hpp"
#include "viz/nice_numbers.hpp"
#include "viz/polygon2d.hpp"

namespace penumbra::viz {

namespace {

using V2 = Eigen::Vector2d;

// One face: its lattice cells clipped to the outline, in face coordinates (a, b) along e1, e2.
class FaceSampler {
 public:
  FaceSampler(SurfaceMesh& mesh, double spacing, double tolerance)
      : mesh_(mesh), spacing_(spacing), tolerance_(tolerance) {}

  void sample(const ConvexPolygon& face, const Vec3& normal, int solid, int faceIndex) {
    const auto& v = face.vertices();
    origin_ = v[0];
    e1_ = (v[1] - v[0]).normalized();
    e2_ = normal.cross(e1_);
    normal_ = normal;
    solid_ = solid;
    corners_.clear();
    std::vector<V2> outline;
    V2 lo = V2::Constant(INFINITY), hi = V2::Constant(-INFINITY);
    for (const Vec3& p : v) {
      outline.emplace_back((p - origin_).dot(e1_), (p - origin_).dot(e2_));
      lo = lo.cwiseMin(outline.back());
      hi = hi.cwiseMax(outline.back());
    }
    const int na = std::max(1, static_cast<int>(std::ceil((hi.x() - lo.x()) / spacing_ - 1e-9)));
    const int nb = std::max(1, static_cast<int>(std::ceil((hi.y() - lo.y()) / spacing_ - 1e-9)));
    const V2 step{(hi.x() - lo.x()) / na, (hi.y() - lo.y()) / nb};
    for (int j = 0; j < nb; ++j) {
      for (int i = 0; i < na; ++i) {
        const V2 c0 = lo + V2(i * step.x(), j * step.y());
        const V2 c1 = lo + V2((i + 1) * step.x(), (j + 1) * step.y());
        std::vector<V2> cell{c0, {c1.x(), c0.y()}, c1, {c0.x(), c1.y()}};
        for (std::size_t k = 0; k < outline.size() && !cell.empty(); ++k) {
          cell = clipLeftOf(cell, outline[k], outline[(k + 1) % outline.size()]);
        }
        if (cell.size() < 3 || signedArea(cell) <= tolerance_ * spacing_) continue;
        addCell(cell, faceIndex);
      }
    }
  }

 private:
  void addCell(const std::vector<V2>& cell, int faceIndex) {
    std::vector<int> ids;
    for (const V2& p : cell) {
      const int id = pointAt(p);
      if (ids.empty() || (ids.back() != id && ids.front() != id)) ids.push_back(id);
    }
    if (ids.size() < 3) return;
    mesh_.cells.push_back(std::move(ids));
    mesh_.cellSolid.push_back(solid_);
    mesh_.cellFace.push_back(faceIndex);
  }

  // Corners shared by neighbouring cells are one point: found by their rounded coordinates.
  int pointAt(const V2& p) {
    const std::pair<long long, long long> key{std::llround(p.x() / tolerance_),
                                              std::llround(p.y() / tolerance_)};
    const auto [it, inserted] = corners_.try_emplace(key, static_cast<int>(mesh_.points.size()));
    if (inserted) {
      SamplePoint point;
      point.position = origin_ + p.x() * e1_ + p.y() * e2_;
      point.normal = normal_;
      point.solid = solid_;
      mesh_.points.push_back(point);
    }
    return it->second;
  }

  SurfaceMesh& mesh_;
  double spacing_, tolerance_;
  Vec3 origin_, e1_, e2_, normal_;
  int solid_ = -1;
  std::map<std::pair<long long, long long>, int> corners_;
};

}  // namespace

double autoSurfaceSpacing(const Scene& scene) {
  const double target = std::max(scene.size(), 1e-3) / 75.0;
  const double below = oneTwoFiveAtMost(target), above = oneTwoFiveAtLeast(target);
  return target / below <= above / target ? below : above;
}

SurfaceMesh sampleSurfaces(const Scene& scene, double spacing) {
  if (!(spacing > 0.0)) throw std::invalid_argument("the surface spacing must be above 0 m");
  // Corners closer than this are one: far below the spacing, far above round-off.
  const double tolerance = 1e3 * Tolerance::forSceneSize(scene.size()).length;
  SurfaceMesh mesh;
  FaceSampler sampler(mesh, spacing, tolerance);
  for (int s = 0; s < static_cast<int>(scene.solids.size()); ++s) {
    const ConvexPolyhedron& shape = scene.solids[s].shape;
    for (int f = 0; f < static_cast<int>(shape.faces().size()); ++f) {
      sampler.sample(shape.facePolygon(f), shape.faces()[f].plane.normal, s, f);
    }
  }
  return mesh;
}

}  // namespace penumbra::viz
