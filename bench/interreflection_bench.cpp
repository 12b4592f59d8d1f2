// Interreflection: what the solver costs and how exact it is.
//  * The example office (data/office.yaml) at element sizes 1.0, 0.5 and 0.25 m: elements,
//    quadrature nodes, seconds per phase (mesh and refinement, element transfer, solve) and
//    the process's peak memory, with the slope of the transfer's time against the element count.
//  * A reflectance study on the office (the carpet's ρ from 0.1 to 0.7), through the estimator a
//    sweep keeps: seconds per case for the total E on every grid; the cases after the first take
//    the transfer from the cache.
//  * CIE 171:2006 case 5.8 (a 4 m cube, 10 000 lm at its centre): the area-average indirect E
//    against ρΦ/(S(1 - ρ)) for ρ from 0.05 to 0.95, from one transfer re-solved per ρ.
//   usage: interreflection_bench [--device cpu|gpu|N] [--sizes 1.0,0.5,0.25]
// Run from the repository root; POCL_MAX_PTHREAD_COUNT=2 pins PoCL to two threads.
#include <fmt/format.h>
#include <sys/resource.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cl/device.hpp"
#include "engine/illuminance_engine.hpp"
#include "grid/grid_evaluation.hpp"
#include "illuminance/estimator.hpp"
#include "radiosity/element_transfer.hpp"
#include "radiosity/interreflection.hpp"
#include "scene/scene_loader.hpp"
#include "timing/seconds_since.hpp"

namespace {

using namespace penumbra;
namespace fs = std::filesystem;

double peakMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

void officeCurve(compute::Device& device, const std::vector<double>& sizes) {
  const Scene scene = loadScene(fs::path(PENUMBRA_SOURCE_DIR) / "data/office.yaml");
  IlluminanceEngine direct(device, scene);
  fmt::print("data/office.yaml\n{:>8} {:>9} {:>8} {:>8} {:>10} {:>8} {:>10} {:>9}\n", "size [m]",
             "elements", "nodes", "mesh [s]", "transfer [s]", "solve [s]", "total [s]",
             "peak [MB]");
  double lastElements = 0.0, lastTransfer = 0.0;
  for (const double size : sizes) {
    MeshOptions options;
    options.elementSize = size;
    const auto start = Clock::now();
    const Interreflection solved(device, scene, direct, options);
    const double total = secondsSince(start);
    const InterreflectionReport& r = solved.report();
    fmt::print("{:>8.3f} {:>9} {:>8} {:>8.2f} {:>12.2f} {:>8.2f} {:>10.2f} {:>9.0f}\n", size,
               r.elements, r.nodes, r.meshSeconds, r.transferSeconds, r.solveSeconds, total,
               peakMegabytes());
    if (lastElements > 0.0) {
      fmt::print("         transfer time ∝ elements^{:.2f}\n",
                 std::log(r.transferSeconds / lastTransfer) /
                     std::log(static_cast<double>(r.elements) / lastElements));
    }
    lastElements = static_cast<double>(r.elements);
    lastTransfer = r.transferSeconds;
  }
}

void reflectanceStudy(const std::string& deviceName) {
  Scene scene = loadScene(fs::path(PENUMBRA_SOURCE_DIR) / "data/office.yaml");
  std::vector<SamplePoint> points;
  for (const CalculationGrid& grid : scene.grids) {
    const std::vector<SamplePoint> gridPoints = gridSamples(scene, grid).outsideSolids();
    points.insert(points.end(), gridPoints.begin(), gridPoints.end());
  }
  int carpet = -1;
  for (std::size_t m = 0; m < scene.materials.size(); ++m)
    if (scene.materials[m].name == "carpet") carpet = static_cast<int>(m);
  EstimatorOptions options;
  options.device = deviceName;
  Estimator estimator(options, scene);
  fmt::print(
      "\ndata/office.yaml, the carpet's reflectance varied ({} grid points)\n"
      "{:>5} {:>10} {:>10} {:>10} {:>9}\n",
      points.size(), "rho", "Eavg [lx]", "case [s]", "transfer", "solve [s]");
  for (const double rho : {0.1, 0.3, 0.5, 0.7}) {
    scene.materials[static_cast<std::size_t>(carpet)].reflectance = Vec3::Constant(rho);
    const auto start = Clock::now();
    estimator.setScene(scene);
    const PointIlluminance e = estimator.illuminance(points);
    const double seconds = secondsSince(start);
    double sum = 0.0;
    for (const double v : e.total) sum += v;
    const InterreflectionReport& r = *estimator.interreflection();
    fmt::print("{:>5.2f} {:>10.2f} {:>10.3f} {:>10} {:>9.3f}\n", rho,
               sum / static_cast<double>(points.size()), seconds,
               r.transferReused ? "reused" : "computed", r.solveSeconds);
  }
}

void cie171Case5_8(compute::Device& device) {
  const fs::path file = fs::temp_directory_path() / "penumbra-bench-cie171-5.8.yaml";
  std::ofstream(file) << "penumbra: 1\nmaterials:\n  paint: 0.5\nroom:\n  size: [4, 4, 4]\n"
                         "  materials: {floor: paint, ceiling: paint, walls: paint}\nsources:\n"
                         "  - {name: lamp, sphere: {center: [2, 2, 2], radius: 0.05}, flux: "
                         "10000}\n";
  const Scene scene = loadScene(file);
  fs::remove(file);
  IlluminanceEngine direct(device, scene);
  const Interreflection solved(device, scene, direct);
  SurfaceMesh mesh = solved.mesh();
  Scene elements = elementScene(scene, mesh);
  IlluminanceEngine engine(device, elements);
  const Eigen::MatrixXd t = elementTransfer(engine, mesh);
  fmt::print("\nCIE 171:2006 case 5.8, {} elements\n{:>5} {:>12} {:>12} {:>10} {:>10}\n",
             mesh.elements.size(), "rho", "E_ind [lx]", "expected", "relative", "solve [s]");
  for (const double rho : {0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95}) {
    for (SurfaceElement& e : mesh.elements) e.reflectance = Vec3::Constant(rho);
    const auto start = Clock::now();
    const RadiositySolution s = solveRadiosity(t, mesh, solved.direct());
    const double seconds = secondsSince(start);
    double sum = 0.0;
    for (std::size_t i = 0; i < mesh.elements.size(); ++i)
      sum += mesh.elements[i].area * s.indirect(static_cast<Eigen::Index>(i), 1);
    const double average = sum / mesh.area();
    const double expected = rho * 10000.0 / (mesh.area() * (1.0 - rho));
    fmt::print("{:>5.2f} {:>12.4f} {:>12.4f} {:>10.2e} {:>10.3f}\n", rho, average, expected,
               (average - expected) / expected, seconds);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string deviceName = "cpu";
  std::vector<double> sizes{1.0, 0.5, 0.25};
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--device") {
      deviceName = argv[i + 1];
    } else if (key == "--sizes") {
      sizes.clear();
      std::stringstream list(argv[i + 1]);
      for (std::string item; std::getline(list, item, ',');) sizes.push_back(std::stod(item));
    } else {
      fmt::print(stderr, "usage: interreflection_bench [--device cpu|gpu|N] [--sizes a,b,...]\n");
      return 2;
    }
  }
  compute::Device device = compute::Device::select(deviceName);
  fmt::print("device: {}\n", device.info().name);
  officeCurve(device, sizes);
  reflectanceStudy(deviceName);
  cie171Case5_8(device);
  return 0;
}
