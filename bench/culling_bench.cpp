// Shadow-volume culling on the open office: work-plane throughput with culling (face
// classes, candidate occluders per patch, umbra/penumbra volumes) and without (every sample
// considers every occluder: the plain path), and how the cost per point grows with the
// number of solids. Prints one JSON line per scene size.
//   usage: culling_bench [--device cpu|gpu|<index>] [--repeat R] [--solids 25,50,100,200,400]
//                        [--floor 1,2,4,8,16] [--write-scene PATH [--solids N | --floor N]]
// --solids: the open office (bench/open_office.hpp) with that many solids in its one room.
// --floor: instead, a floor of that many cellular offices (bench/office_floor.hpp; 29 to 390
// solids for 1 to 16 offices), where solids come with rooms of their own.
#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>

#include "bench/office_floor.hpp"
#include "bench/open_office.hpp"
#include "cl/device.hpp"
#include "engine/illuminance_engine.hpp"
#include "grid/grid_evaluation.hpp"
#include "reference/pyramid_oracle.hpp"
#include "scene/scene_loader.hpp"
#include "shadow/scene_shadows.hpp"

namespace {

using namespace penumbra;

double seconds(auto&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Timing {
  double setup = 0.0;     // engine construction: program, shadow volumes, upload
  double best = 1e30;     // one evaluation of the whole work plane (patch table + kernel)
  double bestCpu = 1e30;  // the same in processor time, all threads (less sensitive to load)
  std::vector<double> e;
  std::vector<ShadowClass> classes;
};

Timing timeEngine(compute::Device& device, const Scene& scene,
                  const std::vector<SamplePoint>& points, bool culling, int repeat) {
  Timing t;
  std::unique_ptr<IlluminanceEngine> engine;
  t.setup = seconds(
      [&] { engine = std::make_unique<IlluminanceEngine>(device, scene, EngineOptions{culling}); });
  engine->illuminance(std::span(points).first(64));  // warm-up: first launch, caches
  // Best of `repeat`, but no more repeats after 20 s (the plain path on the largest floor).
  double spent = 0.0;
  for (int r = 0; r < repeat && spent < 20.0; ++r) {
    IlluminanceResult result;
    const std::clock_t cpu = std::clock();
    const double once = seconds([&] { result = engine->evaluate(points); });
    t.best = std::min(t.best, once);
    spent += once;
    t.bestCpu = std::min(t.bestCpu, static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC);
    t.e = std::move(result.illuminance);
    t.classes = std::move(result.shadowClass);
  }
  return t;
}

// The work the scene asks for, whatever the method: per point, summed over the source faces, the
// occluders that really block part of the face (they meet the pyramid conv(P, face): the exact
// oracle, on every 64th point). A method whose cost follows this number, rather than the count
// of solids, spends its time only where shadows are.
double blockingOccludersPerPoint(const Scene& scene, const std::vector<SamplePoint>& points) {
  const SceneShadows shadows = buildSceneShadows(scene);
  long blocking = 0, sampled = 0;
  for (std::size_t i = 0; i < points.size(); i += 64, ++sampled)
    for (const EmittingFaceShadows& emitting : shadows.faces) {
      if (emitting.face.plane().signedDistance(points[i].position) <= 0.0) continue;
      for (const ShadowCaster& caster : emitting.casters)
        if (caster.solid != points[i].solid &&
            pyramidSeparation(points[i].position, emitting.face.vertices(), caster.shape,
                              shadows.tolerance.length) < -shadows.tolerance.length)
          ++blocking;
    }
  return static_cast<double>(blocking) / static_cast<double>(sampled);
}

// Every grid's points outside the solids.
std::vector<SamplePoint> gridPoints(const Scene& scene) {
  std::vector<SamplePoint> points;
  for (const CalculationGrid& grid : scene.grids) {
    const std::vector<SamplePoint> outside = gridSamples(scene, grid).outsideSolids();
    points.insert(points.end(), outside.begin(), outside.end());
  }
  return points;
}

void run(compute::Device& device, const Scene& scene, int offices, int repeat) {
  const std::vector<SamplePoint> points = gridPoints(scene);

  // For profilers (callgrind counts instructions whatever the machine's load): one mode only.
  const char* only = std::getenv("PENUMBRA_BENCH_ONLY");
  if (only) {
    const Timing t = timeEngine(device, scene, points, std::string(only) == "culled", repeat);
    const nlohmann::json line = {{"solids", scene.solids.size()},
                                 {"offices", offices},
                                 {"mode", only},
                                 {"points", points.size()},
                                 {"best_s", t.best},
                                 {"us_per_point", 1e6 * t.best / points.size()},
                                 {"cpu_us_per_point", 1e6 * t.bestCpu / points.size()}};
    std::cout << line.dump() << std::endl;
    return;
  }
  const Timing culled = timeEngine(device, scene, points, true, repeat);
  const Timing plain = timeEngine(device, scene, points, false, repeat);

  double worst = 0.0, emax = 0.0;
  for (double e : plain.e) emax = std::max(emax, e);
  std::size_t worstAt = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d = std::abs(culled.e[i] - plain.e[i]) / std::max(plain.e[i], 1e-6 * emax);
    if (d > worst) {
      worst = d;
      worstAt = i;
    }
  }
  if (std::getenv("PENUMBRA_BENCH_VERBOSE")) {
    const SamplePoint& p = points[worstAt];
    std::cerr << fmt::format(
        "worst point ({:.6f}, {:.6f}, {:.6f}): culled {:.9g} lx, plain {:.9g} lx\n", p.position.x(),
        p.position.y(), p.position.z(), culled.e[worstAt], plain.e[worstAt]);
    for (int s = 0; s < static_cast<int>(scene.sources.size()); ++s)
      std::cerr << static_cast<int>(culled.classes[worstAt * scene.sources.size() + s]) << ' ';
    std::cerr << '\n';
  }
  std::size_t counts[4] = {0, 0, 0, 0};
  for (ShadowClass c : culled.classes) ++counts[static_cast<int>(c)];
  const double pointSources = static_cast<double>(points.size()) * scene.sources.size();
  const double blocking = blockingOccludersPerPoint(scene, points);

  nlohmann::json line = {
      {"solids", scene.solids.size()},
      {"offices", offices},
      {"device", device.info().name},
      {"points", points.size()},
      {"sources", scene.sources.size()},
      {"culled_setup_s", culled.setup},
      {"culled_s", culled.best},
      {"plain_s", plain.best},
      {"speedup", plain.best / culled.best},
      {"culled_us_per_point", 1e6 * culled.best / points.size()},
      {"plain_us_per_point", 1e6 * plain.best / points.size()},
      {"culled_point_sources_per_s", pointSources / culled.best},
      {"classes_lit_penumbra_umbra_unlit",
       {counts[static_cast<int>(ShadowClass::Lit)], counts[static_cast<int>(ShadowClass::Penumbra)],
        counts[static_cast<int>(ShadowClass::Umbra)],
        counts[static_cast<int>(ShadowClass::Unlit)]}},
      {"max_relative_difference", worst},
      {"blocking_occluders_per_point", blocking},
      {"culled_us_per_blocking_occluder",
       blocking > 0 ? 1e6 * culled.best / points.size() / blocking : 0.0},
  };
  std::cout << line.dump() << std::endl;
}

}  // namespace

int main(int argc, char** argv) {
  std::string deviceSpec = "cpu", solidsList = "25,50,100,200,400", floorList, writeScene;
  int repeat = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--device"))
      deviceSpec = argv[i + 1];
    else if (!std::strcmp(argv[i], "--repeat"))
      repeat = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--solids"))
      solidsList = argv[i + 1];
    else if (!std::strcmp(argv[i], "--floor"))
      floorList = argv[i + 1];
    else if (!std::strcmp(argv[i], "--write-scene"))
      writeScene = argv[i + 1];
  }
  // A scene of the curve: the open office at `n` solids, or (floor) a floor of `n` offices.
  const bool floor = !floorList.empty();
  auto yaml = [&](int n) { return floor ? bench::officeFloorYaml(n) : bench::openOfficeYaml(n); };
  if (!writeScene.empty()) {
    std::ofstream(writeScene) << yaml(std::stoi(floor ? floorList : solidsList));
    return 0;
  }
  compute::Device device = compute::Device::select(deviceSpec);
  std::stringstream list(floor ? floorList : solidsList);
  for (std::string item; std::getline(list, item, ',');) {
    const int n = std::stoi(item);
    run(device, parseScene(yaml(n), floor ? "office-floor.yaml" : "open-office.yaml"),
        floor ? n : 0, repeat);
  }
  return 0;
}
