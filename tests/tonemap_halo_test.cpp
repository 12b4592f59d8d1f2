// Halos (host/tonemap/halo.*): the measure against hand-made display images, and the display maps
// on a synthetic step.
#include "tonemap/halo.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "synthetic_images.hpp"
#include "tonemap/display_spaces.hpp"
#include "tonemap/tone_map.hpp"

namespace penumbra {
namespace {

ScalarImage spaceZero(const testing::HdrScene& scene) {
  const DisplaySpaces spaces = displaySpaces(scene.hdr, 0.02);
  ScalarImage v(spaces.width, spaces.height);
  v.values = spaces.value0;
  return v;
}

// Two faces 1:100 with a lighting gradient down each (×3 from top to bottom).
testing::HdrScene litStep() {
  testing::HdrScene scene = testing::staircase({100.0}, 128, 64, 1.0);
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 256; ++x) {
      float* p = scene.hdr.pixel(x, y);
      p[0] = p[1] = p[2] = p[0] * static_cast<float>(1 + 2 * y / 63.0);
    }
  }
  return scene;
}

template <typename Display>
ScalarImage displayOf(const ScalarImage& scene, Display display) {
  ScalarImage out(scene.width, scene.height);
  for (int y = 0; y < scene.height; ++y) {
    for (int x = 0; x < scene.width; ++x) out.at(x, y) = display(x, y, scene.at(x, y));
  }
  return out;
}

TEST(Halo, NoneWhereEachRegionHasOneGainOrOneCurve) {
  const testing::HdrScene scene = litStep();
  const ScalarImage v0 = spaceZero(scene);
  // A gain per region (a local map without halos), and a global power curve.
  const ScalarImage gains =
      displayOf(v0, [](int x, int, double v) { return v * (x < 128 ? 0.3 : 0.005); });
  const ScalarImage curve = displayOf(v0, [](int, int, double v) { return std::sqrt(v) / 20; });
  for (const ScalarImage* display : {&gains, &curve}) {
    const HaloMeasure halo = measureHalos(v0, scene.faces, *display);
    EXPECT_EQ(halo.regions, 2);
    EXPECT_LT(halo.largest(), 1e-5);
  }
  // A curve of its own per region that bends in log-log, log display = 1.5 (log V₀ − log V₀,min)²
  // at two gains, on the lit step with its four columns next to the edge lit evenly at the middle
  // of each face's range: the near pixels are shown as the far pixels of their luminance are, so
  // no halo. A line through all of a region's far pixels misses such a curve by 0.3 in log at the
  // middle of the range and would call it one.
  testing::HdrScene evenNearTheEdge = scene;
  for (int y = 0; y < 64; ++y) {
    for (int x = 124; x < 132; ++x) {
      float* p = evenNearTheEdge.hdr.pixel(x, y);
      p[0] = p[1] = p[2] = x < 128 ? 2.0f : 200.0f;
    }
  }
  const ScalarImage nearEven = spaceZero(evenNearTheEdge);
  const ScalarImage perRegion = displayOf(nearEven, [](int x, int, double v) {
    const double l = std::log(v / (x < 128 ? 1.0 : 100.0));
    return (x < 128 ? 0.01 : 0.2) * std::exp(1.5 * l * l);
  });
  const HaloMeasure bent = measureHalos(nearEven, evenNearTheEdge.faces, perRegion);
  EXPECT_EQ(bent.regions, 2);
  EXPECT_LT(bent.largest(), 0.01);
}

TEST(Halo, MeasuresALiftNearTheEdge) {
  // The bright side lifted by 20 % next to the edge, decaying over 3 pixels: at distance 0 the
  // lift is 0.2 over a far level lifted by at most 0.2·e⁻⁸ (distance ≥ 24).
  const testing::HdrScene scene = litStep();
  const ScalarImage v0 = spaceZero(scene);
  const ScalarImage lifted = displayOf(v0, [](int x, int, double v) {
    const int distance = x - 128;
    return distance < 0 ? v : v * (1 + 0.2 * std::exp(-distance / 3.0));
  });
  const HaloMeasure halo = measureHalos(v0, scene.faces, lifted);
  EXPECT_NEAR(halo.overshoot, 0.2, 1e-4);
  EXPECT_LT(halo.undershoot, 1e-5);
  // Mean over the near pixels of both regions: the bright side's four distances, 64 pixels each,
  // lifted by 0.2 e^(-d/3); the dark side's, unlifted, 62 each (its two top rows, within 5 % of
  // the image's darkest value, count as held at black).
  const double lift = 0.2 * (1 + std::exp(-1 / 3.0) + std::exp(-2 / 3.0) + std::exp(-1.0));
  EXPECT_NEAR(halo.meanDeviation, 64 * lift / (4 * 64 + 4 * 62), 1e-4);
}

// The constraint map on a step 1:100 beside a window and on the lit step: on the level lattice
// (the default) each face is one curve of its luminance by construction; on the image lattice the
// region rows hold each face to one curve, so nothing near the edge departs from it. The image
// lattice with region rows ten times weaker than the edge rows (medium 1, strong 10) lets the
// edge rows bend the faces: the measure sees that halo.
TEST(Halo, ConstraintMapShowsNoHaloOnASyntheticStep) {
  const testing::HdrScene besideWindow = testing::stepBesideWindow(128, 64, 32);
  const testing::HdrScene lit = litStep();
  for (const testing::HdrScene* scene : {&besideWindow, &lit}) {
    const ScalarImage v0 = spaceZero(*scene);
    ToneMapOptions options;
    const HaloMeasure levels =
        measureHalos(v0, scene->faces, displayValues(scene->hdr, scene->faces, options));
    EXPECT_EQ(levels.regions, 2);
    // A curve per region: 0 but for the local line's own error where the curve bends within 10 %
    // of luminance (1.1e-3 on the lit step, 8e-8 on the flat one, measured).
    EXPECT_LT(levels.largest(), 0.005);
    options.vertices = VertexLattice::Image;
    const HaloMeasure image =
        measureHalos(v0, scene->faces, displayValues(scene->hdr, scene->faces, options));
    EXPECT_EQ(image.regions, 2);
    EXPECT_LT(image.largest(), 0.01);
    options.medium = 1;
    const HaloMeasure bent =
        measureHalos(v0, scene->faces, displayValues(scene->hdr, scene->faces, options));
    std::cout << "halo on the step: levels " << levels.largest() << ", image lattice "
              << image.largest() << ", image lattice with medium = 1: " << bent.largest() << "\n";
    EXPECT_GT(bent.largest(), 0.01);
  }
}

}  // namespace
}  // namespace penumbra
