// An occluder's edge that lies within the tie tolerance of a source edge's side plane without
// lying in it: a bezel round a ceiling panel, whose lip's image on the panel falls within a few
// hundredths of a millimetre of the panel's edge, seen from 4° below the ceiling. The tie rule
// (kernels/contour.cl) reads the lip's edge as lying in the panel edge's plane and drops it; the
// edges beside it must then end where the panel's edge does, or the visible contour stays open by
// up to the tolerance. Seen nearly edge-on, Lambert's terms cancel several hundredfold, and that
// gap cost several % of E. What the tie rule may still change is a band of the tolerance's width
// along the edge the lips are tied to: E is held within L · 2 · kKernelTie · (that edge's angle
// at P) of the exact integral.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/illuminance_engine.hpp"
#include "geometry/tolerance.hpp"
#include "penumbra_paths.hpp"
#include "reference/exact_illuminance.hpp"
#include "test_device.hpp"
#include "test_scenes.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;

constexpr double kLuminance = 1000.0;  // cd/m²

// The panel, 0.6 × 0.3 m at 3 m facing down, and its bezel: four boxes 0.05 m outside its edges,
// 0.03 m wide, 0.01 to 0.04 m below the ceiling plane (`boxes` of them: the lip on the −y side
// first).
Scene bezelScene(int boxes) {
  Scene scene;
  scene.sources.push_back(areaSource(
      {{0.7, 0.35, 3.0}, {0.7, 0.65, 3.0}, {1.3, 0.65, 3.0}, {1.3, 0.35, 3.0}}, kLuminance));
  const Solid bezel[4] = {boxSolid({0.62, 0.27, 2.96}, {1.38, 0.30, 2.99}, "lip -y"),
                          boxSolid({0.62, 0.70, 2.96}, {1.38, 0.73, 2.99}, "lip +y"),
                          boxSolid({1.35, 0.30, 2.96}, {1.38, 0.70, 2.99}, "lip +x"),
                          boxSolid({0.62, 0.30, 2.96}, {0.65, 0.70, 2.99}, "lip -x")};
  for (int i = 0; i < boxes; ++i) scene.solids.push_back(bezel[i]);
  return scene;
}

// The angle the panel's x = 1.3 m edge subtends at P: the edge the lips' edges are tied to.
double tiedEdgeAngle(const Scene& scene, const Vec3& p) {
  const auto& v = scene.sources.front().faces.front().vertices();
  const Vec3 a = v[2] - p, b = v[3] - p;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

TEST(NearTie, ALipJustInsideAPanelsEdgeKeepsTheContourClosedOnEveryPath) {
  // Points 4° below the ceiling, 2.7 m from the panel, along a line on which the image of the
  // lip's end edge crosses the panel's x = 1.3 m edge (near dx = −3.1 mm): within the tie
  // tolerance of its side plane over about ±0.4 mm of dx (tied), out of it beyond (not tied); the
  // receiver faces the panel at 20° to its horizon.
  std::vector<SamplePoint> points;
  for (int k = -20; k <= 20; ++k) {
    const double dx = -3.1e-3 + 5e-5 * k;
    points.push_back({Vec3(2.8101675217765725 + dx, -1.4540322440484688, 2.8116121176298092),
                      Vec3(-0.27690590806481297, 0.29891325880994946, -0.91322175936976979), -1});
  }
  const auto paths = penumbraPaths();
  for (const int boxes : {1, 4}) {
    const Scene scene = bezelScene(boxes);
    const std::vector<double> exact = exactIlluminance(scene, points)[0];
    for (const auto& path : paths) {
      IlluminanceEngine engine(cpuDevice(), scene, path.options);
      const std::vector<double> e = engine.illuminance(points);
      double worst = 0.0, worstShare = 0.0;
      for (std::size_t i = 0; i < points.size(); ++i) {
        const double bound =
            kLuminance * 2.0 * Tolerance::kKernelTie * tiedEdgeAngle(scene, points[i].position);
        const double error = std::abs(e[i] - exact[i]);
        EXPECT_LE(error, bound) << boxes << " boxes, " << path.name << ", point " << i
                                << ": E = " << e[i] << " lx, exact " << exact[i] << " lx";
        worst = std::max(worst, error / exact[i]);
        worstShare = std::max(worstShare, error / bound);
      }
      std::printf(
          "  %d box(es), %s path: largest |E − exact| %.1e of E, %.2f of the tie rule's bound\n",
          boxes, path.name, worst, worstShare);
    }
  }
}

}  // namespace
}  // namespace penumbra
