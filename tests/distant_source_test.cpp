// Penumbrae of a small, distant source, held against an exact answer computed another way.
//
// A 0.6 m ceiling panel 10 m from the point, partly hidden by a chair back 0.4 m from it (the open
// office's far panels seen past the near furniture). The occlusion tests' criterion (2e-3 of the
// unoccluded value, tests/occlusion_test.cpp) is set by the reference's sampling, and it let the
// kernel err by up to 2.0e-3 (eight-lane path) and 1.3e-3 (scalar path) of this panel's light
// here: the visible contour was assembled from crossing points each edge computed for itself, and
// a gap of δ rad in a contour costs about L·δ however small the source looks (kernels/
// illuminance.cl, crossing_point). Every path is held to 1e-4 of the panel's unoccluded value,
// twice the float rounding of the unoccluded formula itself at these points (5.4e-5 measured: the
// terms of a source 10 m away cancel to 1/175 of their size). Measured: 6.1e-5 eight lanes,
// 5.4e-5 scalar and plain.
//
// The exact value: the box above P's horizon, projected from P onto the panel's plane, is a convex
// polygon; E is the contour integral (double) over the panel minus that polygon.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "lighting/illuminance_engine.hpp"
#include "test_device.hpp"
#include "test_scenes.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;
using Vec2 = Eigen::Vector2d;

double cross2(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Convex hull, counter-clockwise (Andrew's monotone chain).
std::vector<Vec2> convexHull(std::vector<Vec2> p) {
  std::sort(p.begin(), p.end(), [](const Vec2& a, const Vec2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::vector<Vec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross2(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross2(h[k - 1] - h[k - 2], p[i] - h[k - 2]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

// The part of a convex polygon left of the directed line a → b.
std::vector<Vec2> clipLeftOf(const std::vector<Vec2>& polygon, const Vec2& a, const Vec2& b) {
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& p = polygon[i];
    const Vec2& q = polygon[(i + 1) % polygon.size()];
    const double fp = cross2(b - a, p - a), fq = cross2(b - a, q - a);
    if (fp >= 0) out.push_back(p);
    if ((fp >= 0) != (fq >= 0)) out.push_back(p + (q - p) * (fp / (fp - fq)));
  }
  return out;
}

// E at P (normal +z) from a polygon on the plane z = height facing down, luminance L: Lambert's
// contour integral in double.
double polygonIlluminance(const std::vector<Vec2>& polygon, const Vec3& p, double height,
                          double luminance) {
  if (polygon.size() < 3) return 0.0;
  double sum = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& u = polygon[i];
    const Vec2& w = polygon[(i + 1) % polygon.size()];
    const Vec3 a(u.x() - p.x(), u.y() - p.y(), height - p.z());
    const Vec3 b(w.x() - p.x(), w.y() - p.y(), height - p.z());
    const Vec3 c = a.cross(b);
    sum += std::atan2(c.norm(), a.dot(b)) * c.z() / c.norm();
  }
  return std::abs(0.5 * luminance * sum);
}

struct PanelPastBox {
  Vec2 panelMin, panelMax;
  double height, luminance;
  Vec3 boxMin, boxMax;

  // Exact E at p (p below the panel, normal +z): the panel minus the box's shadow on its plane.
  double exact(const Vec3& p, double* unoccluded) const {
    const std::vector<Vec2> panel = {
        panelMin, {panelMax.x(), panelMin.y()}, panelMax, {panelMin.x(), panelMax.y()}};
    *unoccluded = polygonIlluminance(panel, p, height, luminance);
    // Segments from P to the panel rise, so only the box above P's horizon can block them; the
    // sliver within 1e-6 m of the horizon projects kilometres away, far off the panel.
    std::vector<Vec2> shadow;
    for (double x : {boxMin.x(), boxMax.x()})
      for (double y : {boxMin.y(), boxMax.y()})
        for (double z : {boxMin.z(), boxMax.z()}) {
          const double zc = std::max(z, p.z() + 1e-6);
          if (zc > boxMax.z()) return *unoccluded;  // the whole box is below the horizon
          const double k = (height - p.z()) / (zc - p.z());
          shadow.push_back({p.x() + k * (x - p.x()), p.y() + k * (y - p.y())});
        }
    shadow = convexHull(shadow);
    std::vector<Vec2> hidden = panel;
    for (std::size_t i = 0; i < shadow.size() && hidden.size() >= 3; ++i)
      hidden = clipLeftOf(hidden, shadow[i], shadow[(i + 1) % shadow.size()]);
    return *unoccluded - polygonIlluminance(hidden, p, height, luminance);
  }
};

// The open office's panel at (1.5, 1.5) and the chair back of its workstation 20, seen from the
// work plane beside that chair: points from full light through the penumbra into the umbra.
TEST(DistantSource, PenumbraPastANearBoxMeetsTheExactProjection) {
  const PanelPastBox setup{{1.2, 1.2}, {1.8, 1.8},        2.99,
                           3006.26,    {9.97, 5.95, 0.5}, {10.43, 6.0, 0.95}};
  Scene scene;
  scene.sources.push_back(ceilingRect(setup.panelMin.x(), setup.panelMin.y(), setup.panelMax.x(),
                                      setup.panelMax.y(), setup.height, setup.luminance));
  scene.solids.push_back(boxSolid(setup.boxMin, setup.boxMax, "chair-back"));
  std::vector<SamplePoint> points;
  for (int i = 0; i <= 50; ++i)
    for (int j = 0; j <= 20; ++j)
      points.push_back({Vec3(10.4 + 0.01 * i, 6.25 + 0.01 * j, 0.8), Vec3::UnitZ(), -1});
  std::vector<double> exact(points.size()), unoccluded(points.size());
  int penumbra = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    exact[k] = setup.exact(points[k].position, &unoccluded[k]);
    if (exact[k] > 1e-3 * unoccluded[k] && exact[k] < (1 - 1e-3) * unoccluded[k]) ++penumbra;
  }
  ASSERT_GE(penumbra, 200) << "the points should cross the penumbra";

  Scene open = scene;
  open.solids.clear();
  const std::vector<double> lit = IlluminanceEngine(cpuDevice(), open).illuminance(points);
  double floorError = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k)
    floorError = std::max(floorError, std::abs(lit[k] - unoccluded[k]) / unoccluded[k]);
  std::printf("unoccluded formula: max |E - exact| / E_unoccluded = %.2e\n", floorError);
  const struct {
    const char* name;
    EngineOptions options;
  } paths[] = {{"culled, eight lanes", {true, true, true}},
               {"culled, scalar", {true, true, false}},
               {"plain (--no-culling)", {false}}};
  for (const auto& path : paths) {
    const std::vector<double> e =
        IlluminanceEngine(cpuDevice(), scene, path.options).illuminance(points);
    double worst = 0.0;
    for (std::size_t k = 0; k < points.size(); ++k) {
      const double error = std::abs(e[k] - exact[k]) / unoccluded[k];
      worst = std::max(worst, error);
      EXPECT_LE(error, 1e-4) << path.name << " at (" << points[k].position.transpose()
                             << "): E = " << e[k] << " lx, exact " << exact[k] << " lx";
    }
    std::printf("%s: %zu points (%d in the penumbra), max |E - exact| / E_unoccluded = %.2e\n",
                path.name, points.size(), penumbra, worst);
  }
}

}  // namespace
}  // namespace penumbra
