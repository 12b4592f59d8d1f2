// Curved primitives: does the laminae placement of Conway & Cottingham pay?
//  1. A sphere and a cylinder as receivers under a ceiling panel: mean and max relative error of
//     E on the facets against E on the smooth surface at the same points, for N = 8, 16, 32, with
//     the facets placed as the paper's laminae (a vertex / ring towards the light) and turned by
//     half a step (a facet towards the light).
//  2. A luminous sphere as a polyhedron source: E below it against π·L·(r/d)²·cos θ, by N.
//   usage: primitives_bench [--device cpu|gpu|<index>]
#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "cl/device.hpp"
#include "engine/facet_error.hpp"
#include "engine/illuminance_engine.hpp"
#include "geometry/primitives.hpp"

namespace {

using namespace penumbra;
constexpr double kPi = std::numbers::pi;

// Points on the unit sphere, evenly spread (a Fibonacci lattice).
std::vector<Vec3> fibonacciDirections(int count) {
  std::vector<Vec3> out;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = 1.0 - 2.0 * (i + 0.5) / count;
    const double r = std::sqrt(1.0 - z * z);
    out.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return out;
}

Source panel(const Vec3& centre, double size, double luminance) {
  const double h = size / 2;
  Source s;
  s.name = "panel";
  // Counter-clockwise about -z.
  s.faces.push_back(ConvexPolygon({centre + Vec3(-h, -h, 0), centre + Vec3(-h, h, 0),
                                   centre + Vec3(h, h, 0), centre + Vec3(h, -h, 0)}));
  s.luminance = luminance;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  std::string deviceSpec = "auto";
  for (int i = 1; i + 1 < argc; i += 2)
    if (!std::strcmp(argv[i], "--device")) deviceSpec = argv[i + 1];
  compute::Device device = compute::Device::select(deviceSpec);

  // A 0.6 m panel 1.5 m above the primitives, straight above and 0.8 m and 2.6 m aside: light
  // from about 0°, 30° and 60° off the axis. Figures are the mean (and the largest) over the
  // three.
  const std::vector<Vec3> panels{Vec3(0.0, 0.0, 1.5), Vec3(0.8, 0.0, 1.5), Vec3(2.6, 0.3, 1.5)};
  const Vec3 centre = Vec3::Zero();
  const double r = 0.3;
  const std::vector<Vec3> directions = fibonacciDirections(4000);
  std::vector<SamplePoint> sphere;
  for (const Vec3& d : directions) sphere.push_back(SamplePoint{centre + r * d, d, -1});
  // Cylinder: axis z, height 0.6, its side only (points at |z| < 0.27 on the smooth side).
  std::vector<SamplePoint> cylinder;
  for (const Vec3& d : directions) {
    const Vec3 radial(d.x(), d.y(), 0.0);
    if (radial.norm() < 1e-6 || std::abs(d.z()) > 0.9) continue;
    const Vec3 normal = radial.normalized();
    cylinder.push_back(SamplePoint{centre + r * normal + Vec3(0, 0, 0.3 * d.z()), normal, -1});
  }

  fmt::print(
      "Receivers: E on the facets against the smooth surface (points with E >= 10 % of the "
      "largest), over three light directions\n");
  fmt::print("{:<9} {:>3} {:>20} {:>20}\n", "shape", "N", "laminae mean / max",
             "turned mean / max");
  for (int n : {8, 16, 32}) {
    for (int shape = 0; shape < 2; ++shape) {
      FacetError e[2];
      for (const Vec3& at : panels) {
        Scene lit;
        lit.sources.push_back(panel(at, 0.6, 3000.0));
        IlluminanceEngine engine(device, lit);
        const Vec3 light = (at - centre).normalized();
        for (int placement = 0; placement < 2; ++placement) {
          const FacetPlacement p =
              placement == 0 ? FacetPlacement::Laminae : FacetPlacement::Turned;
          const ConvexPolyhedron facets =
              shape == 0
                  ? tessellate(SphereShape{centre, r}, n, light, p, 1e-9)
                  : tessellate(TruncusShape{centre, Vec3(0, 0, 0.6), r, r}, n, light, p, 1e-9);
          const FacetError one =
              facetError(engine, facets, centre, shape == 0 ? sphere : cylinder, 0.1);
          e[placement].mean += one.mean / panels.size();
          e[placement].max = std::max(e[placement].max, one.max);
        }
      }
      fmt::print("{:<9} {:>3} {:>9.2e} / {:>8.2e} {:>9.2e} / {:>8.2e}\n",
                 shape == 0 ? "sphere" : "cylinder", n, e[0].mean, e[0].max, e[1].mean, e[1].max);
    }
  }

  fmt::print(
      "\nA luminous sphere (r = 0.2 m, L = 1000 cd/m²) 1.5 m above the floor, point at "
      "x = 0.5 m: E against pi·L·(r/d)²·cos θ\n");
  fmt::print("{:>3} {:>8} {:>14} {:>14} {:>10}\n", "N", "faces", "E_lx", "closed_lx", "rel_err");
  const Vec3 globe(0.0, 0.0, 1.5);
  const SamplePoint p{Vec3(0.5, 0.0, 0.0), Vec3::UnitZ(), -1};
  const Vec3 toGlobe = globe - p.position;
  const double d = toGlobe.norm();
  const double closed = kPi * 1000.0 * (0.2 / d) * (0.2 / d) * toGlobe.z() / d;
  for (int n : {4, 8, 16, 32, 45}) {
    Scene scene;
    Source s;
    s.name = "globe";
    s.shape = SourceShape::Polyhedron;
    s.luminance = 1000.0;
    const ConvexPolyhedron shape =
        tessellate(SphereShape{globe, 0.2}, n, Vec3::UnitZ(), FacetPlacement::Laminae, 1e-9);
    for (int f = 0; f < static_cast<int>(shape.faces().size()); ++f)
      s.faces.push_back(shape.facePolygon(f));
    scene.sources.push_back(s);
    IlluminanceEngine globeEngine(device, scene);
    const double e = globeEngine.illuminance(std::vector<SamplePoint>{p})[0];
    fmt::print("{:>3} {:>8} {:>14.6f} {:>14.6f} {:>10.2e}\n", n, shape.faces().size(), e, closed,
               (e - closed) / closed);
  }
  return 0;
}
