// The exact reference in double (exact_illuminance.hpp says what it is for). Per point P and
// source face F: the boundary of the part of F that P sees (visible_boundary.hpp), and
// E = L/2 · Σ θ · n·unit(b × a) over its pieces a → b (vectors from P), in double; for a
// luminance polynomial in w·ω (a luminaire's opening, the overcast sky), E = L · Σ c_k M_k with
// the moments M_k of cosine_moments.hpp over the same boundary.
//
// Shares no code with kernels/ or the shadow volumes in host/shadow.
#include "reference/exact_illuminance.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "geometry/tolerance.hpp"
#include "reference/cosine_moments.hpp"
#include "reference/visible_boundary.hpp"

namespace penumbra {
namespace {

struct ExactFace {
  int source = 0;
  ConvexPolygon polygon;
  FaceFrame frame;
  double luminance = 0.0;
  std::vector<double> coefficients;  // of the luminance polynomial in axis·ω; empty: uniform
  Vec3 axis = Vec3::Zero();
};

double faceIlluminance(const ExactFace& face, const SamplePoint& point, const Scene& scene,
                       double tolerance) {
  const Vec3 n = point.normal.normalized();
  const std::vector<VisibleArc> arcs =
      visibleBoundary(face.polygon, face.frame, point, scene, tolerance);
  if (face.coefficients.size() > 1) {
    const int order = static_cast<int>(face.coefficients.size()) - 1;
    const std::vector<double> moments = cosineMoments(arcs, face.axis, n, order);
    double sum = 0.0;
    for (int k = 0; k <= order; ++k) sum += face.coefficients[k] * moments[k];
    return face.luminance * sum;
  }
  double sum = 0.0;
  for (const VisibleArc& arc : arcs) {
    const Vec3 m = arc.to.cross(arc.from);
    const double s = m.norm();
    if (s > 0.0) sum += std::atan2(s, arc.from.dot(arc.to)) * n.dot(m) / s;
  }
  const double c0 = face.coefficients.empty() ? 1.0 : face.coefficients[0];
  return face.luminance * c0 * 0.5 * sum;
}

}  // namespace

std::vector<std::vector<double>> exactIlluminance(const Scene& scene,
                                                  std::span<const SamplePoint> points,
                                                  bool perSource) {
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  std::vector<ExactFace> faces;
  for (int s = 0; s < static_cast<int>(scene.sources.size()); ++s) {
    const Source& source = scene.sources[s];
    for (const ConvexPolygon& polygon : source.faces) {
      if (polygon.empty() || source.luminance == 0.0 || polygon.area() <= 0.0) continue;
      ExactFace face;
      face.source = s;
      face.polygon = polygon;
      face.luminance = source.luminance;
      face.coefficients = source.luminanceCoefficients;
      face.axis = source.polynomialAxis(polygon);
      face.frame = FaceFrame::of(polygon);
      faces.push_back(std::move(face));
    }
  }
  const std::size_t rows = perSource ? scene.sources.size() : 1;
  std::vector<std::vector<double>> out(rows, std::vector<double>(points.size(), 0.0));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, points.size(), 16),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i < r.end(); ++i)
                        for (const ExactFace& face : faces)
                          out[perSource ? face.source : 0][i] +=
                              faceIlluminance(face, points[i], scene, tolerance);
                    });
  return out;
}

}  // namespace penumbra
