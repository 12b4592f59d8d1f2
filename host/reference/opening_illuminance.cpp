#include "reference/opening_illuminance.hpp"

#include "reference/cosine_moments.hpp"
#include "reference/visible_boundary.hpp"

namespace penumbra {

ConvexPolygon placedOutline(std::span<const Vec3> outline, const LuminaireInstance& instance) {
  std::vector<Vec3> vertices;
  vertices.reserve(outline.size());
  for (const Vec3& v : outline) vertices.push_back(instance.position + instance.toScene * v);
  return ConvexPolygon(std::move(vertices));
}

ConvexPolygon placedOpening(const LuminaireOpening& opening, const LuminaireInstance& instance) {
  return placedOutline(opening.outline, instance);
}

double openingIlluminance(const Luminaire& luminaire, const LuminaireInstance& instance,
                          const SamplePoint& point, const Scene& scene, double tolerance) {
  const LuminaireOpening& opening = *luminaire.opening;
  const ConvexPolygon polygon = placedOpening(opening, instance);
  const FaceFrame frame = FaceFrame::of(polygon);
  const std::vector<VisibleArc> arcs = visibleBoundary(polygon, frame, point, scene, tolerance);
  if (arcs.empty()) return 0.0;
  const std::vector<double>& c = opening.fit.coefficients;
  const std::vector<double> moments =
      cosineMoments(arcs, -frame.normal, point.normal.normalized(), opening.fit.order());
  double sum = 0.0;
  for (std::size_t k = 0; k < c.size(); ++k) sum += c[k] * moments[k];
  return luminaire.intensityScale * sum;
}

}  // namespace penumbra
