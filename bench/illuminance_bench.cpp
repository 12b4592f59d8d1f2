// Throughput of the illuminance kernel in point·sources per second:
//  (a) an unoccluded grid: a work plane under ceiling panels in an empty room;
//  (b) a penumbra-heavy grid: most points partly shadowed by several boxes;
// each on the chosen device (default PoCL's CPU device; POCL_MAX_PTHREAD_COUNT=2 pins two
// threads), and the ratio to the reference estimator at n = 64 on the same points.
// Prints one JSON line per case.
//   usage: illuminance_bench [--device cpu|gpu|<index>] [--points N] [--repeat R]
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <random>
#include <string>

#include "cl/device.hpp"
#include "engine/illuminance_engine.hpp"
#include "reference/reference_illuminance.hpp"

namespace {

using namespace penumbra;

Source panel(double cx, double cy, double z, double size, double luminance) {
  const double h = size / 2;
  Source s;
  s.name = "panel";
  // Counter-clockwise about the emission direction -z.
  s.faces.push_back(ConvexPolygon(
      {{cx - h, cy - h, z}, {cx - h, cy + h, z}, {cx + h, cy + h, z}, {cx + h, cy - h, z}}));
  s.luminance = luminance;
  return s;
}

void addRoom(Scene& scene) {
  const double t = 0.2;
  auto box = [&](Vec3 lo, Vec3 hi, const char* name) {
    scene.solids.push_back(Solid{name, ConvexPolyhedron::box(lo, hi), -1});
  };
  box({-t, -t, -t}, {6 + t, 4 + t, 0}, "floor");
  box({-t, -t, 3}, {6 + t, 4 + t, 3 + t}, "ceiling");
  box({-t, -t, 0}, {6 + t, 0, 3}, "wall-y0");
  box({-t, 4, 0}, {6 + t, 4 + t, 3}, "wall-y1");
  box({-t, 0, 0}, {0, 4, 3}, "wall-x0");
  box({6, 0, 0}, {6 + t, 4, 3}, "wall-x1");
}

Scene unoccludedScene() {
  Scene scene;
  addRoom(scene);
  for (double x : {1.5, 4.5})
    for (double y : {1.0, 3.0}) scene.sources.push_back(panel(x, y, 2.99, 0.6, 3000.0));
  return scene;
}

Scene penumbraScene() {
  Scene scene = unoccludedScene();
  // Twelve boxes hanging between the panels and the work plane: every point sees several of
  // them cut across some panel.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 12; ++k) {
    const Vec3 c(0.5 + 5.0 * u(random), 0.5 + 3.0 * u(random), 1.4 + 1.0 * u(random));
    const Vec3 half(0.15 + 0.3 * u(random), 0.15 + 0.3 * u(random), 0.05 + 0.1 * u(random));
    scene.solids.push_back(Solid{"box", ConvexPolyhedron::box(c - half, c + half), -1});
  }
  return scene;
}

std::vector<SamplePoint> workPlane(int count) {
  const int side = static_cast<int>(std::sqrt(static_cast<double>(count)));
  std::vector<SamplePoint> points;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i)
      points.push_back(
          {Vec3(6.0 * (i + 0.5) / side, 4.0 * (j + 0.5) / side, 0.8), Vec3::UnitZ(), -1});
  return points;
}

double seconds(auto&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void run(const std::string& name, const Scene& scene, compute::Device& device, int pointCount,
         int repeat, int referencePoints) {
  const std::vector<SamplePoint> points = workPlane(pointCount);
  IlluminanceEngine engine(device, scene);
  engine.illuminance(std::span(points).first(64));  // warm-up: first launch, caches
  double best = 1e30;
  std::vector<double> e;
  for (int r = 0; r < repeat; ++r)
    best = std::min(best, seconds([&] { e = engine.illuminance(points); }));
  const double pointSources = static_cast<double>(points.size()) * scene.sources.size();

  // The reference on a subset (it is slow), scaled to a rate.
  const std::vector<SamplePoint> subset(
      points.begin(), points.begin() + std::min<std::size_t>(referencePoints, points.size()));
  const double referenceSeconds = seconds([&] { referenceIlluminance(scene, subset, 64); });
  const double referenceRate =
      static_cast<double>(subset.size()) * scene.sources.size() / referenceSeconds;

  int shaded = 0;
  Scene open = scene;
  open.solids.clear();
  IlluminanceEngine openEngine(device, open);
  const std::vector<double> unoccluded = openEngine.illuminance(points);
  for (std::size_t i = 0; i < points.size(); ++i) shaded += e[i] < 0.999 * unoccluded[i];

  nlohmann::json line = {
      {"case", name},
      {"device", device.info().name},
      {"points", points.size()},
      {"sources", scene.sources.size()},
      {"solids", scene.solids.size()},
      {"shaded_fraction", static_cast<double>(shaded) / points.size()},
      {"seconds", best},
      {"point_sources_per_s", pointSources / best},
      {"reference_n64_point_sources_per_s", referenceRate},
      {"speedup_vs_reference_n64", pointSources / best / referenceRate},
  };
  std::cout << line.dump() << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  std::string deviceSpec = "cpu";
  int points = 256 * 256, repeat = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--device"))
      deviceSpec = argv[i + 1];
    else if (!std::strcmp(argv[i], "--points"))
      points = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--repeat"))
      repeat = std::atoi(argv[i + 1]);
  }
  compute::Device device = compute::Device::select(deviceSpec);
  run("unoccluded", unoccludedScene(), device, points, repeat, 2000);
  run("penumbra", penumbraScene(), device, points / 4, repeat, 500);
  return 0;
}
