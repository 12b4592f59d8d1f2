// Results do not depend on how a polygon is written down (start vertex, orientation), and a
// polyhedron source's per-face sum equals the contour integral over its silhouette (Nishita
// §2.5(1)).
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>

#include "engine/illuminance_engine.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"
#include "test_scenes.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;

std::string polygonText(std::vector<Vec3> v) {
  std::string text = "[";
  for (std::size_t i = 0; i < v.size(); ++i)
    text += (i ? ", [" : "[") + std::to_string(v[i].x()) + ", " + std::to_string(v[i].y()) + ", " +
            std::to_string(v[i].z()) + "]";
  return text + "]";
}

// A panel with an explicit normal and a shelf under it, written with the given vertex lists.
Scene sceneWith(const std::vector<Vec3>& source, const std::vector<Vec3>& shelfBase) {
  const std::string yaml =
      "penumbra: 1\n"
      "solids:\n"
      "  - {name: shelf, prism: {base: " +
      polygonText(shelfBase) +
      ", height: 0.1}}\n"
      "sources:\n"
      "  - {name: panel, polygon: " +
      polygonText(source) +
      ", normal: [0, 0, -1], luminance: 2000}\n"
      "grids:\n"
      "  - {name: floor, rect: {origin: [-1.5, -1.5, 0], u: [3, 0, 0], v: [0, 3, 0]}, "
      "spacing: 0.25}\n";
  return parseScene(yaml, "invariance.yaml");
}

std::vector<double> floorE(const Scene& scene) {
  std::vector<SamplePoint> points;
  const CalculationGrid& grid = scene.grids.at(0);
  for (std::size_t i = 0; i < grid.size(); ++i)
    points.push_back({grid.position(i), grid.normal(i), -1});
  IlluminanceEngine engine(cpuDevice(), scene);
  return engine.illuminance(points);
}

TEST(Invariance, VertexOrderAndStartVertexChangeNothing) {
  std::vector<Vec3> panel = {
      {-0.4, -0.3, 2.5}, {0.5, -0.3, 2.5}, {0.6, 0.4, 2.5}, {-0.4, 0.4, 2.5}};
  std::vector<Vec3> shelf = {
      {-0.2, -0.6, 1.2}, {0.4, -0.6, 1.2}, {0.4, 0.1, 1.2}, {-0.2, 0.1, 1.2}};
  const std::vector<double> reference = floorE(sceneWith(panel, shelf));
  int shaded = 0;
  for (double e : reference)
    shaded += e < 0.999 * *std::max_element(reference.begin(), reference.end());
  ASSERT_GT(shaded, 10);
  for (int variant = 0; variant < 6; ++variant) {
    std::vector<Vec3> p = panel, s = shelf;
    if (variant & 1) std::reverse(p.begin(), p.end());
    if (variant & 2) std::reverse(s.begin(), s.end());
    std::rotate(p.begin(), p.begin() + variant % 4, p.end());
    std::rotate(s.begin(), s.begin() + (variant + 1) % 4, s.end());
    const std::vector<double> e = floorE(sceneWith(p, s));
    ASSERT_EQ(e.size(), reference.size());
    for (std::size_t i = 0; i < e.size(); ++i)
      EXPECT_NEAR(e[i], reference[i], 1e-5 * reference[i] + 1e-6)
          << "variant " << variant << " point " << i;
  }
}

// Lambert's contour integral in double over a closed loop of vertices (host, test only).
double contourIntegral(const std::vector<Vec3>& loop, const Vec3& p, const Vec3& n, double L) {
  double sum = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3 a = loop[i] - p, b = loop[(i + 1) % loop.size()] - p;
    const Vec3 c = b.cross(a);
    sum += std::atan2(c.norm(), a.dot(b)) * n.dot(c) / c.norm();
  }
  return 0.5 * L * sum;
}

TEST(Invariance, PolyhedronSourceEqualsItsSilhouetteIntegral) {
  // A luminous box seen from points all around it, above its horizon: the sum over its faces
  // (what the kernel does) equals the integral over the contour line alone (the paper's form).
  const ConvexPolyhedron body = ConvexPolyhedron::box({-0.2, -0.3, 1.0}, {0.3, 0.2, 1.4});
  Source cube;
  cube.name = "cube";
  cube.shape = SourceShape::Polyhedron;
  for (std::size_t f = 0; f < body.faces().size(); ++f)
    cube.faces.push_back(body.facePolygon(static_cast<int>(f)));
  cube.luminance = 1000;
  Scene scene;
  scene.sources.push_back(cube);
  std::vector<SamplePoint> points;
  for (double x : {-1.5, -0.1, 0.8})
    for (double z : {0.0, 0.5, 1.2, 2.5})
      points.push_back({Vec3(x, 0.7, z), Vec3(0, -0.6, 0.8) * (z > 1.2 ? -1 : 1), -1});
  IlluminanceEngine engine(cpuDevice(), scene);
  const std::vector<double> e = engine.illuminance(points);
  int compared = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    // Every silhouette vertex must be above the point's horizon for the plain contour form.
    const std::vector<Vec3> loop = body.silhouette(points[i].position);
    ASSERT_GE(loop.size(), 4u);
    bool above = true;
    for (const Vec3& v : loop) above &= points[i].normal.dot(v - points[i].position) > 0;
    if (!above) continue;
    const double expected = contourIntegral(loop, points[i].position, points[i].normal, 1000);
    EXPECT_NEAR(e[i], expected, 1e-5 * std::abs(expected)) << points[i].position.transpose();
    ++compared;
  }
  EXPECT_GE(compared, 8);
}

}  // namespace
}  // namespace penumbra
