// Curved primitives (docs/primitives.md): the tessellation, primitives in scene files, and a
// luminous sphere against its closed form and the independent reference.
#include "geometry/primitives.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/illuminance_engine.hpp"
#include "reference/reference_illuminance.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"

namespace penumbra {
namespace {

using testing::cpuDevice;
constexpr double kPi = std::numbers::pi;
constexpr double kTol = 1e-9;

TEST(Tessellation, ASphereIsInscribedWithAPoleTowardsTheLight) {
  const SphereShape sphere{Vec3(1, 2, 3), 0.5};
  const Vec3 light = Vec3(1, 1, 2).normalized();
  double previousVolume = 0.0;
  for (int n : {4, 8, 16}) {
    const ConvexPolyhedron shape = tessellate(sphere, n, light, FacetPlacement::Laminae, kTol);
    // 2N segments around, N bands: triangles at the poles, quads between.
    EXPECT_EQ(shape.faces().size(), static_cast<std::size_t>(2 * n * n));
    bool pole = false;
    for (const Vec3& v : shape.vertices()) {
      EXPECT_NEAR((v - sphere.center).norm(), sphere.radius, 1e-12);
      pole |= (v - (sphere.center + sphere.radius * light)).norm() < 1e-12;
    }
    EXPECT_TRUE(pole);
    // Inscribed: the volume grows towards 4/3·π·r³ from below.
    const double volume = shape.volume();
    EXPECT_LT(volume, 4.0 / 3.0 * kPi * std::pow(sphere.radius, 3));
    EXPECT_GT(volume, previousVolume);
    previousVolume = volume;
  }
  // Turned by half a step: a flat cap faces the light.
  const ConvexPolyhedron turned = tessellate(sphere, 8, light, FacetPlacement::Turned, kTol);
  bool cap = false;
  for (const auto& face : turned.faces()) cap |= face.plane.normal.dot(light) > 1.0 - 1e-12;
  EXPECT_TRUE(cap);
}

TEST(Tessellation, ATruncusHasARimVertexTowardsTheLight) {
  // The paper's truncus: E1 (r1) at centre + axis/2, E2 (r2) at centre − axis/2.
  const TruncusShape frustum{Vec3(0, 0, 1), Vec3(0, 0, 2), 0.3, 0.5};
  const Vec3 light = Vec3(1, 0, 1).normalized();  // L_E = +x
  const ConvexPolyhedron shape = tessellate(frustum, 12, light, FacetPlacement::Laminae, kTol);
  EXPECT_EQ(shape.faces().size(), 14u);  // 12 sides and the two ends
  bool towards = false;
  for (const Vec3& v : shape.vertices()) {
    const double radius = std::hypot(v.x(), v.y());
    EXPECT_NEAR(radius, v.z() > 1.0 ? 0.3 : 0.5, 1e-12);
    towards |= (v - Vec3(0.3, 0, 2)).norm() < 1e-12;
  }
  EXPECT_TRUE(towards);
  const ConvexPolyhedron cone = tessellate(TruncusShape{Vec3::Zero(), Vec3(0, 0, 1), 0.0, 0.4}, 10,
                                           light, FacetPlacement::Laminae, kTol);
  EXPECT_EQ(cone.faces().size(), 11u);  // 10 sides and the base
  // A regular N-gon of circumradius r has area N/2·r²·sin(2π/N); the cone is a third of it × h.
  EXPECT_NEAR(cone.volume(), 10.0 / 2.0 * 0.16 * std::sin(2 * kPi / 10) / 3.0, 1e-12);
}

TEST(PrimitivesInScenes, AreReadAndFaceTheStrongestSource) {
  const Scene scene = parseScene(R"(penumbra: 1
solids:
  - {name: globe, sphere: {center: [0, 0, 1], radius: 0.2, facets: 6}}
  - {name: column, cylinder: {center: [2, 0, 1.5], axis: [0, 0, 3], radius: 0.15}}
  - {name: shade, cone: {center: [0, 2, 2], axis: [0, 0, 0.3], radius: 0.25, facets: 8}}
  - {name: bevel, truncus: {center: [1, 1, 0.5], axis: [0, 0, 0.2], r1: 0.1, r2: 0.3}}
sources:
  - {name: dim, rect: {center: [-3, 0, 2.5], size: [0.3, 0.3], normal: [0, 0, -1]}, luminance: 100}
  - {name: bright, rect: {center: [0, 0, 2.5], size: [0.6, 0.6], normal: [0, 0, -1]}, luminance: 3000}
  - {name: lamp, sphere: {center: [4, 4, 2], radius: 0.1, facets: 4}, luminance: 500}
)",
                                 "test.yaml");
  ASSERT_EQ(scene.solids.size(), 4u);
  EXPECT_EQ(scene.solids[0].shape.faces().size(), 72u);  // 2·6²
  EXPECT_EQ(scene.solids[1].shape.faces().size(), 18u);  // the default 16 sides and two ends
  EXPECT_EQ(scene.solids[2].shape.faces().size(), 9u);
  EXPECT_EQ(scene.solids[3].shape.faces().size(), 18u);
  // The globe's pole points at the bright panel straight above it, not at the dim one.
  bool pole = false;
  for (const Vec3& v : scene.solids[0].shape.vertices())
    pole |= (v - Vec3(0, 0, 1.2)).norm() < 1e-9;
  EXPECT_TRUE(pole);
  // A luminous sphere is a polyhedron source: every face emits.
  EXPECT_EQ(scene.sources[2].shape, SourceShape::Polyhedron);
  EXPECT_EQ(scene.sources[2].faces.size(), 32u);
}

TEST(PrimitivesInScenes, Errors) {
  const auto errorOf = [](const std::string& solid) -> std::string {
    try {
      parseScene("penumbra: 1\nsolids:\n  - " + solid + "\n", "test.yaml");
    } catch (const SceneError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_NE(errorOf("{name: a, sphere: {center: [0, 0, 0], radius: 0}}").find("greater than 0"),
            std::string::npos);
  EXPECT_NE(errorOf("{name: a, sphere: {center: [0, 0, 0], radius: 1, facets: 2.5}}")
                .find("test.yaml:3: solids[0].sphere.facets: facets is a whole number"),
            std::string::npos);
  EXPECT_NE(errorOf("{name: a, cylinder: {center: [0, 0, 0], axis: [0, 0, 1], radius: 1, "
                    "facets: 2}}")
                .find("from 3"),
            std::string::npos);
  EXPECT_NE(errorOf("{name: a, cone: {center: [0, 0, 0], axis: [0, 0, 0], radius: 1}}")
                .find("cannot be zero"),
            std::string::npos);
  EXPECT_NE(errorOf("{name: a, truncus: {center: [0, 0, 0], axis: [0, 0, 1], r1: 0, r2: 0}}")
                .find("at least one radius"),
            std::string::npos);
  EXPECT_NE(
      errorOf("{name: a, truncus: {center: [0, 0, 0], axis: [0, 0, 1], radius: 1}}").find("radius"),
      std::string::npos);
}

Scene luminousSphere(const Vec3& centre, double radius, int facets, double luminance) {
  Scene scene;
  Source source;
  source.name = "globe";
  source.shape = SourceShape::Polyhedron;
  source.luminance = luminance;
  const ConvexPolyhedron shape =
      tessellate(SphereShape{centre, radius}, facets, Vec3::UnitZ(), FacetPlacement::Laminae, kTol);
  for (int f = 0; f < static_cast<int>(shape.faces().size()); ++f)
    source.faces.push_back(shape.facePolygon(f));
  scene.sources.push_back(source);
  return scene;
}

TEST(LuminousSphere, ConvergesToTheClosedFormAsFacetsGrow) {
  // E = π·L·(r/d)²·cos θ for a sphere wholly above the point's horizon.
  const Vec3 globe(0, 0, 1.5);
  const SamplePoint p{Vec3(0.5, 0, 0), Vec3::UnitZ(), -1};
  const Vec3 toGlobe = globe - p.position;
  const double d = toGlobe.norm();
  const double closed = kPi * 1000.0 * std::pow(0.2 / d, 2) * toGlobe.z() / d;
  std::vector<double> errors;
  for (int n : {8, 16, 32}) {
    IlluminanceEngine engine(cpuDevice(), luminousSphere(globe, 0.2, n, 1000.0));
    const double e = engine.illuminance(std::vector<SamplePoint>{p})[0];
    errors.push_back(std::abs(e - closed) / closed);
    std::printf("luminous sphere N = %d: E = %.6f lx, closed form %.6f lx, error %.2e\n", n, e,
                closed, errors.back());
  }
  // An inscribed polyhedron loses area as 1/N²: each doubling divides the error by about 4.
  EXPECT_GT(errors[0] / errors[1], 3.0);
  EXPECT_GT(errors[1] / errors[2], 3.0);
  EXPECT_LT(errors[2], 3e-3);
}

TEST(LuminousSphere, PartlyBelowTheHorizonAgreesWithTheReference) {
  // The globe's centre 0.1 m above the floor and 0.4 m aside: a third of it is below the
  // horizon of floor points next to it.
  const Scene scene = luminousSphere(Vec3(0, 0, 0.1), 0.2, 12, 1000.0);
  std::vector<SamplePoint> points;
  for (double x : {0.25, 0.3, 0.4, 0.6}) points.push_back({Vec3(x, 0.05, 0), Vec3::UnitZ(), -1});
  IlluminanceEngine engine(cpuDevice(), scene);
  const std::vector<double> kernel = engine.illuminance(points);
  const std::vector<double> reference = referenceIlluminance(scene, points, 256);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_GT(kernel[i], 0.0);
    EXPECT_NEAR(kernel[i], reference[i], 1e-4 * reference[i]) << "x = " << points[i].position.x();
  }
}

TEST(SphereOccluder, CastsTheShadowTheReferenceCasts) {
  // A globe of 512 faces (more than a 64-bit face mask could hold) under a ceiling panel: floor
  // points in its umbra, penumbra and light against the independent reference.
  Scene scene;
  Source panel;
  panel.name = "panel";
  panel.faces.push_back(
      ConvexPolygon({{-0.3, -0.3, 2.5}, {-0.3, 0.3, 2.5}, {0.3, 0.3, 2.5}, {0.3, -0.3, 2.5}}));
  panel.luminance = 3000.0;
  scene.sources.push_back(panel);
  scene.solids.push_back(Solid{"globe",
                               tessellate(SphereShape{Vec3(0, 0, 1.0), 0.25}, 16, Vec3::UnitZ(),
                                          FacetPlacement::Laminae, kTol),
                               -1});
  ASSERT_EQ(scene.solids[0].shape.faces().size(), 512u);
  std::vector<SamplePoint> points;
  for (double x : {0.0, 0.1, 0.2, 0.3, 0.4, 0.6, 1.0})
    points.push_back({Vec3(x, 0.02, 0), Vec3::UnitZ(), -1});
  IlluminanceEngine engine(cpuDevice(), scene);
  const std::vector<double> kernel = engine.illuminance(points);
  const std::vector<double> reference = referenceIlluminance(scene, points, 256);
  EXPECT_EQ(kernel[0], 0.0);  // under the globe's centre: umbra
  EXPECT_GT(kernel.back(), 0.0);
  const double scale = *std::max_element(reference.begin(), reference.end());
  for (std::size_t i = 0; i < points.size(); ++i)
    EXPECT_NEAR(kernel[i], reference[i], 1e-4 * scale) << "x = " << points[i].position.x();
}

}  // namespace
}  // namespace penumbra
