// A narrow beam's high powers (the azimuth form's backward sweep, kernels/luminance_moments.cl)
// at points all round the luminaire: E finite, never negative, and the double reference's to a
// few millionths of the peak. Far down the sweep's tail x^{j−1} underflows where (f/x)^{j−1}
// overflows; their product is what the sweep needs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "luminaire_test_support.hpp"
#include "photometry_files.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

using namespace penumbra::testing;
namespace tf = photometry::testfiles;

constexpr double kPi = std::numbers::pi;

// Points on spheres of 0.5 to 6 m round `centre` (a Fibonacci lattice of 400 directions each),
// each facing the centre and tilted by up to 60° in a direction that turns with the point.
std::vector<SamplePoint> pointsAllRound(const Vec3& centre) {
  std::vector<SamplePoint> points;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (const double radius : {0.5, 1.0, 2.0, 4.0, 6.0})
    for (int i = 0; i < 400; ++i) {
      const double z = 1.0 - (i + 0.5) / 200.0, r = std::sqrt(1.0 - z * z);
      const Vec3 dir(r * std::cos(golden * i), r * std::sin(golden * i), z);
      const Vec3 inward = -dir;
      const Vec3 side = inward.unitOrthogonal();
      const double tilt = (i % 7) * kPi / 18.0, turn = i * 0.7;
      const Vec3 across = std::cos(turn) * side + std::sin(turn) * inward.cross(side);
      points.push_back({centre + radius * dir,
                        (std::cos(tilt) * inward + std::sin(tilt) * across).normalized(), -1});
    }
  return points;
}

TEST(NarrowBeams, AreFiniteAndMatchTheReferenceAllRoundTheLuminaire) {
  TempDir dir("narrow-beam");
  // A spot (1 + cos²⁴γ) / 2 from a 0.6 × 0.3 m opening (powers to 22) and a downlight
  // 0.03 + 0.97 cos³⁹γ from a 0.15 m disk (powers 0 and 38), tilted 20°.
  struct Case {
    const char* name;
    double a;
    int power;
    double length, width;
  };
  const Case cases[] = {{"spot", 0.5, 24, 0.6, 0.3}, {"downlight", 0.03, 39, 0.0, -0.15}};
  const Vec3 centre(1.0, 0.5, 3.0);
  const std::vector<SamplePoint> points = pointsAllRound(centre);
  for (const Case& c : cases) {
    tf::IesSpec spec;
    spec.vertical = tf::steps(0, 180, 1);
    spec.horizontal = {0};
    spec.length = c.length;
    spec.width = c.width;
    spec.candela = [&](double, double gammaDeg) {
      const double g = std::cos(gammaDeg * kPi / 180);
      return gammaDeg < 90 ? 1000.0 * g * (c.a + (1 - c.a) * std::pow(g, c.power)) : 0.0;
    };
    const auto file = writeFile(dir.path(), std::string(c.name) + ".ies", tf::iesText(spec));
    Scene scene;
    scene.luminaires.push_back(
        placeLuminaire({file, centre, LuminaireAim{30.0, 20.0}, 1.0, LuminaireModel::Area}));
    ASSERT_GT(scene.luminaires.front().opening->fit.order(), 12) << c.name;
    const std::vector<double> kernel = kernelE(scene, points);
    const std::vector<double> exact = referenceE(scene, points);
    const double peak = *std::max_element(exact.begin(), exact.end());
    double worst = 0.0;
    int lit = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      ASSERT_TRUE(std::isfinite(kernel[i])) << c.name << " at " << points[i].position.transpose();
      EXPECT_GE(kernel[i], 0.0) << c.name << " at " << points[i].position.transpose();
      worst = std::max(worst, std::abs(kernel[i] - exact[i]) / peak);
      EXPECT_LE(std::abs(kernel[i] - exact[i]), 5e-6 * peak)
          << c.name << " at " << points[i].position.transpose();
      lit += exact[i] > 0.0;
    }
    EXPECT_GT(lit, 500) << c.name;
    std::printf("  %s (order %d): %d of %zu points lit, largest |E − exact| %.2e of the peak\n",
                c.name, scene.luminaires.front().opening->fit.order(), lit, points.size(), worst);
  }
}

}  // namespace
}  // namespace penumbra
