// `penumbra grid` end to end, in point·sources per second: a 12 × 8 m floor of 960 000 points
// (1200 × 800, every 10 mm) under eight 3400 lm Lambertian panels, unoccluded, and the same floor
// with twelve boxes hanging between the panels and the floor. Each scene is run as a user runs
// it (the binary, a fresh process, the CSV and .res written) and its wall time split into
//   load      reading and building the scene (summary.json load_s)
//   setup     device, program build (from PoCL's cache), shadow tables (setup_s)
//   kernel    the same grid through the same batches without writing anything (this process)
//   writing   what the written run's grid took beyond that (time_s − kernel): the files' share
//             that the kernel batches did not hide (noise can make it negative)
//   leaving   the rest of the process's wall time: the last batch's rows, summary.json, the
//             staged directory's rename, tear-down and exit, and the process's start (loading
//             its shared libraries)
// Direct light only (`--direct-only`): the rate is the kernel's and the outputs', which the
// interreflection's mesh, transfer and final gather would otherwise swamp (interreflection_bench
// and hierarchy_bench measure those).
// Two rates per scene: over the whole wall time, and over what the dense run costs beyond a
// sparse one (120 × 80 points) of the same scene, which leaves out every fixed cost. Each of R
// repeats prints its runs; then a line of the least wall time of each kind (best) and one of
// each kind's median wall time (median: on a shared virtual machine single runs vary by ±20 %,
// and the best dense run less the best sparse one can flatter).
// PoCL is pinned to two threads (POCL_MAX_PTHREAD_COUNT=2) unless the environment says otherwise.
//   usage: end_to_end_bench [--device cpu|gpu|<index>] [--repeat R] [--keep DIR] [--binary PATH]
// --binary runs another build of penumbra (an older one, to compare); the kernel alone is always
// this build's.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "grid/grid_evaluation.hpp"
#include "illuminance/estimator.hpp"
#include "scene/scene_loader.hpp"

namespace {

namespace fs = std::filesystem;
using namespace penumbra;

std::string binary = PENUMBRA_BINARY;  // --binary

constexpr double kLength = 12.0, kWidth = 8.0, kHeight = 3.0;  // interior, m

// The floor scene: `spacing` 0.01 gives the 1200 × 800 dense grid, 0.1 the 120 × 80 sparse one.
std::string floorYaml(double spacing, bool boxes) {
  std::string yaml = fmt::format(
      "penumbra: 1\n"
      "materials: {{white: 0.85, paint: 0.7, carpet: 0.2, grey: 0.5}}\n"
      "room:\n"
      "  size: [{}, {}, {}]\n"
      "  wall_thickness: 0.2\n"
      "  materials: {{floor: carpet, ceiling: white, walls: paint}}\n"
      "sources:\n",
      kLength, kWidth, kHeight);
  int panel = 0;
  for (double x : {1.5, 4.5, 7.5, 10.5})
    for (double y : {2.0, 6.0})
      yaml += fmt::format(
          "  - {{name: panel-{}, rect: {{center: [{}, {}, 2.99], size: [0.6, 0.6], "
          "normal: [0, 0, -1]}}, flux: 3400}}\n",
          ++panel, x, y);
  if (boxes) {
    // Twelve boxes between the panels and the floor: every point sees several of them cut
    // across some panel.
    yaml += "solids:\n";
    std::mt19937 random(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int k = 0; k < 12; ++k) {
      const double cx = 1.0 + 10.0 * u(random), cy = 1.0 + 6.0 * u(random);
      const double cz = 1.4 + 1.0 * u(random);
      const double hx = 0.15 + 0.3 * u(random), hy = 0.15 + 0.3 * u(random);
      const double hz = 0.05 + 0.1 * u(random);
      yaml += fmt::format(
          "  - {{name: box-{}, box: {{min: [{:.4f}, {:.4f}, {:.4f}], max: [{:.4f}, {:.4f}, "
          "{:.4f}]}}, material: grey}}\n",
          k + 1, cx - hx, cy - hy, cz - hz, cx + hx, cy + hy, cz + hz);
    }
  }
  yaml += fmt::format(
      "grids:\n"
      "  - {{name: floor, rect: {{origin: [0, 0, 0], u: [{}, 0, 0], v: [0, {}, 0]}}, "
      "spacing: {}}}\n",
      kLength, kWidth, spacing);
  return yaml;
}

double secondsOf(auto&& f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Run {
  double wall = 0, cpu = 0;                         // s; cpu: the process's user + system time
  double load = 0, setup = 0, grid = 0, total = 0;  // summary.json
  std::size_t points = 0;
};

double seconds(const timeval& t) {
  return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec;
}

// Runs `penumbra grid scene -o output --quiet` and reads its summary.json.
Run runBinary(const fs::path& scene, const fs::path& output, const std::string& device) {
  fs::remove_all(output);
  std::vector<std::string> arguments = {binary,          "grid",    scene.string(),  "-o",
                                        output.string(), "--quiet", "--direct-only", "--device",
                                        device};
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  int status = -1;
  rusage usage{};
  Run run;
  run.wall = secondsOf([&] {
    pid_t pid = -1;
    if (posix_spawn(&pid, binary.c_str(), &actions, nullptr, argv.data(), environ) != 0)
      throw std::runtime_error("cannot start " + binary);
    wait4(pid, &status, 0, &usage);
  });
  posix_spawn_file_actions_destroy(&actions);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("penumbra grid failed on " + scene.string());
  run.cpu = seconds(usage.ru_utime) + seconds(usage.ru_stime);
  std::ifstream in(output / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  run.load = summary["timing"]["load_s"].get<double>();
  run.setup = summary["timing"]["setup_s"].get<double>();
  run.total = summary["timing"]["total_s"].get<double>();
  for (const auto& grid : summary["grids"]) {
    run.grid += grid["time_s"].get<double>();
    run.points += grid["points"].get<std::size_t>();
  }
  return run;
}

// The grid through the same batches as `penumbra grid`, nothing written: classification and the
// estimator only.
double kernelSeconds(const fs::path& scenePath, const std::string& device) {
  const Scene scene = loadScene(scenePath, {});
  EstimatorOptions options;
  options.device = device;
  options.interreflection = false;  // as `--direct-only`
  Estimator estimator(options, scene);
  double seconds = 0.0;
  for (const CalculationGrid& grid : scene.grids)
    seconds += streamGrid(scene, grid, estimator.function(), estimator.batchSize(), {}).seconds;
  return seconds;
}

constexpr int kSources = 8;

void print(const std::string& label, const Run& d, const Run& s, double kernel) {
  const double pointSources = static_cast<double>(d.points) * kSources;
  const double marginal = static_cast<double>(d.points - s.points) * kSources / (d.wall - s.wall);
  const double writing = d.grid - kernel;
  const double leaving = d.wall - d.load - d.setup - d.grid;
  fmt::print(
      "{:<16} wall {:.3f} s (cpu {:.3f})  {:5.1f} M point·sources/s whole, {:5.1f} M beyond the "
      "sparse run ({:.3f} s, cpu {:.3f})\n"
      "{:<16} split: load {:.3f}  setup {:.3f}  kernel {:.3f}  writing {:+.3f}  leaving {:.3f} s"
      "   kernel alone {:.1f} M/s\n",
      label, d.wall, d.cpu, pointSources / d.wall / 1e6, marginal / 1e6, s.wall, s.cpu, "", d.load,
      d.setup, kernel, writing, leaving, pointSources / kernel / 1e6);
  const nlohmann::json line = {
      {"case", label},
      {"points", d.points},
      {"sources", kSources},
      {"wall_s", d.wall},
      {"cpu_s", d.cpu},
      {"sparse_wall_s", s.wall},
      {"point_sources_per_s", pointSources / d.wall},
      {"marginal_point_sources_per_s", marginal},
      {"load_s", d.load},
      {"setup_s", d.setup},
      {"kernel_s", kernel},
      {"writing_s", writing},
      {"leaving_s", leaving},
  };
  fmt::print("{}\n", line.dump());
  std::fflush(stdout);
}

// The run of median wall time among `runs` (the upper one of an even count).
Run medianRun(std::vector<Run> runs) {
  const auto middle = runs.begin() + static_cast<std::ptrdiff_t>(runs.size() / 2);
  std::nth_element(runs.begin(), middle, runs.end(),
                   [](const Run& a, const Run& b) { return a.wall < b.wall; });
  return *middle;
}

// Each run, then the best of them (the least wall time of each kind: the machine is shared) and
// the median (each kind's median wall time: less sensitive than the best to one lucky sparse run).
void runCase(const std::string& name, bool boxes, const fs::path& directory,
             const std::string& device, int repeat) {
  const fs::path dense = directory / (name + "-dense.yaml");
  const fs::path sparse = directory / (name + "-sparse.yaml");
  std::ofstream(dense) << floorYaml(0.01, boxes);
  std::ofstream(sparse) << floorYaml(0.1, boxes);
  Run bestDense, bestSparse;
  double bestKernel = 0;
  std::vector<Run> denseRuns, sparseRuns;
  std::vector<double> kernels;
  for (int r = 0; r < repeat; ++r) {
    const Run d = runBinary(dense, directory / (name + "-dense"), device);
    const Run s = runBinary(sparse, directory / (name + "-sparse"), device);
    const double kernel = kernelSeconds(dense, device);
    print(fmt::format("{} run {}", name, r + 1), d, s, kernel);
    if (r == 0 || d.wall < bestDense.wall) bestDense = d;
    if (r == 0 || s.wall < bestSparse.wall) bestSparse = s;
    if (r == 0 || kernel < bestKernel) bestKernel = kernel;
    denseRuns.push_back(d);
    sparseRuns.push_back(s);
    kernels.push_back(kernel);
  }
  print(fmt::format("{} best", name), bestDense, bestSparse, bestKernel);
  const auto middle = kernels.begin() + static_cast<std::ptrdiff_t>(kernels.size() / 2);
  std::nth_element(kernels.begin(), middle, kernels.end());
  print(fmt::format("{} median", name), medianRun(denseRuns), medianRun(sparseRuns), *middle);
}

}  // namespace

int main(int argc, char** argv) {
  std::string device = "cpu";
  int repeat = 3;
  fs::path keep;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--device"))
      device = argv[i + 1];
    else if (!std::strcmp(argv[i], "--repeat"))
      repeat = std::max(1, std::atoi(argv[i + 1]));
    else if (!std::strcmp(argv[i], "--keep"))
      keep = argv[i + 1];
    else if (!std::strcmp(argv[i], "--binary"))
      binary = argv[i + 1];
  }
  setenv("POCL_MAX_PTHREAD_COUNT", "2", 0);
  const fs::path directory =
      keep.empty() ? fs::temp_directory_path() / fmt::format("end_to_end_bench-{}", getpid())
                   : keep;
  fs::create_directories(directory);
  try {
    runCase("unoccluded", false, directory, device, repeat);
    runCase("boxes", true, directory, device, repeat);
  } catch (const std::exception& e) {
    fmt::print(stderr, "end_to_end_bench: {}\n", e.what());
    return 1;
  }
  if (keep.empty()) fs::remove_all(directory);
  return 0;
}
