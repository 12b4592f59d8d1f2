#include "glare/seen_sources.hpp"

#include "geometry/sample_point.hpp"
#include "geometry/tolerance.hpp"
#include "reference/opening_illuminance.hpp"
#include "reference/region_solid_angle.hpp"
#include "reference/visible_boundary.hpp"

namespace penumbra {
namespace {

// A flat luminous area as the eye sees it: the solid angle of its visible part, and A·cos φ / d².
struct FaceView {
  double solidAngle = 0.0, farFieldAngle = 0.0;
};

FaceView viewOf(const ConvexPolygon& face, const Vec3& eye, const Scene& scene, double tolerance) {
  if (face.empty() || face.area() <= 0.0) return {};
  const FaceFrame frame = FaceFrame::of(face);
  const Vec3 toCentre = face.centroid() - eye;
  const double cosine = -frame.normal.dot(toCentre.normalized());
  if (cosine <= 0.0) return {};  // the eye is behind the face or in its plane
  // The eye's horizon parallel to the face: all of a face the eye is in front of lies above it.
  const SamplePoint point{eye, -frame.normal, -1};
  const std::vector<VisibleArc> arcs = visibleBoundary(face, frame, point, scene, tolerance);
  FaceView view;
  if (!arcs.empty()) view.solidAngle = regionSolidAngle(arcs, toCentre.normalized());
  view.farFieldAngle = face.area() * cosine / toCentre.squaredNorm();
  return view;
}

Vec3 areaCentre(const std::vector<ConvexPolygon>& faces) {
  Vec3 weighted = Vec3::Zero();
  double area = 0.0;
  for (const ConvexPolygon& face : faces) {
    if (face.empty()) continue;
    weighted += face.area() * face.centroid();
    area += face.area();
  }
  return area > 0.0 ? Vec3(weighted / area) : Vec3::Zero();
}

}  // namespace

EyeView seenSources(const Scene& scene, const Vec3& eye) {
  const double tolerance = Tolerance::forSceneSize(scene.size()).length;
  EyeView view;
  for (const Source& source : scene.sources) {
    if (source.luminance <= 0.0) continue;
    SeenSource seen{source.name, source.luminance, 0.0, 0.0, areaCentre(source.faces) - eye};
    for (const ConvexPolygon& face : source.faces) {
      const FaceView faceView = viewOf(face, eye, scene, tolerance);
      seen.solidAngle += faceView.solidAngle;
      seen.farFieldAngle += faceView.farFieldAngle;
    }
    if (seen.solidAngle > 0.0) view.sources.push_back(std::move(seen));
  }
  for (const Luminaire& luminaire : scene.luminaires) {
    for (const LuminaireInstance& instance : luminaire.instances) {
      if (luminaire.luminousOutline.empty()) {
        ++view.withoutArea;
        continue;
      }
      const ConvexPolygon opening = placedOutline(luminaire.luminousOutline, instance);
      const FaceView faceView = viewOf(opening, eye, scene, tolerance);
      if (faceView.solidAngle <= 0.0) continue;
      const Vec3 toEye = eye - instance.position;
      const double projectedArea = opening.area() * opening.normal().dot(toEye.normalized());
      const double intensity =
          luminaire.intensity(instance.toScene.transpose() * toEye.normalized());
      view.sources.push_back(SeenSource{instance.name, intensity / projectedArea,
                                        faceView.solidAngle, faceView.farFieldAngle,
                                        opening.centroid() - eye});
    }
  }
  return view;
}

}  // namespace penumbra
