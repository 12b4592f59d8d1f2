// The constraint tone map on synthetic room views (tests/synthetic_images.hpp: window, luminaires,
// walls with falloff, boxes with penumbra ramps) at 640x360, 1280x720 and 1920x1080 (the
// target: 1280x720 under 1 s). Each size runs in its own child process so that its peak memory
// (ru_maxrss) is its own. Prints one JSON line per size: the tone map's statistics and time, and
// the solver comparison: the two-stage solver (primal-dual active set, projected Newton when the
// active set cycles) against projected gradient with Barzilai-Borwein steps, the usual
// factorisation-free alternative, run to the same objective.
//   usage: tonemap_bench [--repeat R] [--boxes N] [--sizes 640x360,1280x720,1920x1080]
//                        [--no-gradient]
//          tonemap_bench --write-scene DIR [--sizes WxH] [--boxes N]
//            writes DIR/room.exr and DIR/room.faceid.exr (the first size) and exits, for
//            `penumbra tonemap` and bench/pfstmo_compare.sh
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "output/image_files.hpp"
#include "tests/synthetic_images.hpp"
#include "timing/seconds_since.hpp"
#include "tonemap/bounded_least_squares.hpp"
#include "tonemap/constraint_system.hpp"
#include "tonemap/display_spaces.hpp"
#include "tonemap/edge_contrast.hpp"
#include "tonemap/region_map.hpp"
#include "tonemap/tone_map.hpp"
#include "tonemap/vertex_mesh.hpp"

namespace {

using namespace penumbra;

double peakMegabytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;
}

// Projected gradient with Barzilai-Borwein steps on ½xᵀQx - cᵀx, until the objective is within
// 1e-9 (relative) of `best` or `limit` iterations.
nlohmann::json projectedGradient(const ConstraintSystem& system, double best, int limit) {
  const auto start = Clock::now();
  const Eigen::SparseMatrix<double> at = system.matrix.transpose();
  const Eigen::SparseMatrix<double> q = at * system.matrix;
  const Eigen::VectorXd c = at * system.target;
  const auto project = [&](const Eigen::VectorXd& x) {
    return Eigen::VectorXd(x.cwiseMax(system.lower).cwiseMin(system.upper));
  };
  const auto objective = [&](const Eigen::VectorXd& x) { return 0.5 * x.dot(q * x) - c.dot(x); };
  Eigen::VectorXd x = project(system.start), g = q * x - c;
  double step = 1.0 / q.diagonal().maxCoeff();
  int iterations = 0;
  double f = objective(x);
  for (; iterations < limit && f - best > 1e-9 * std::abs(best); ++iterations) {
    const Eigen::VectorXd next = project(x - step * g);
    const Eigen::VectorXd gNext = q * next - c;
    const Eigen::VectorXd s = next - x, y = gNext - g;
    const double sy = s.dot(y);
    step = sy > 0 ? s.dot(s) / sy : step;
    x = next, g = gNext, f = objective(x);
  }
  return {{"iterations", iterations},
          {"reached", f - best <= 1e-9 * std::abs(best)},
          {"seconds", secondsSince(start)}};
}

nlohmann::json benchSize(int width, int height, int boxes, int repeat, bool gradient) {
  const testing::HdrScene scene = testing::roomView(width, height, boxes);
  const double imageMegabytes = peakMegabytes();
  ToneMapOptions options;  // the documented defaults
  ToneMapStats stats;
  std::vector<double> times;
  ScalarImage display;
  for (int r = 0; r < repeat; ++r) {
    const auto start = Clock::now();
    display = displayValues(scene.hdr, scene.faces, options, &stats);
    times.push_back(secondsSince(start));
  }
  std::sort(times.begin(), times.end());
  nlohmann::json line = {
      {"size", std::to_string(width) + "x" + std::to_string(height)},
      {"regions", stats.regions},
      {"variables", stats.variables},
      {"rows", stats.strongRows + stats.mediumRows + stats.weakRows},
      {"three_variable_rows", stats.threeVariableRows},
      {"active_set_iterations", stats.activeSetIterations},
      {"projected_newton_iterations", stats.projectedNewtonIterations},
      {"converged", stats.converged},
      {"seconds_median", times[times.size() / 2]},
      {"seconds_min", times.front()},
      {"build_s", stats.buildSeconds},
      {"solve_s", stats.solveSeconds},
      {"pixels_s", stats.pixelSeconds},
      {"peak_rss_mb", peakMegabytes()},
      {"rss_before_tonemap_mb", imageMegabytes},
  };
  const double black = options.black;
  const ScalarImage linear =
      displayValues(scene.hdr, scene.faces, ToneMapOptions{DisplayMethod::Linear, black});
  const ScalarImage clip =
      displayValues(scene.hdr, scene.faces, ToneMapOptions{DisplayMethod::Clip, black});
  const std::vector<std::pair<const char*, const ScalarImage*>> maps = {
      {"constraint", &display}, {"linear", &linear}, {"clip", &clip}};
  for (const auto& [name, image] : maps) {
    const EdgeContrastShare share =
        measureEdgeContrast(scene.hdr, scene.faces, *image, black, 0.05);
    line["edges_kept_5pct"][name] = share.share();
    line["edges_kept_5pct_displayable"][name] =
        share.displayable ? double(share.kept) / share.displayable : 1.0;
  }
  if (gradient) {
    const DisplaySpaces spaces = displaySpaces(scene.hdr, black);
    const RegionMap regions = findRegions(scene.faces);
    const VertexMesh mesh = buildVertexMesh(regions, options.lattice);
    const ConstraintSystem system = buildConstraintSystem(
        mesh, regions, logScene(spaces, regions), {options.strong, options.medium, options.weak});
    const auto start = Clock::now();
    const auto solved = solveBoundedLeastSquares(system.matrix, system.target, system.lower,
                                                 system.upper, system.start);
    const double ours = secondsSince(start);
    const Eigen::VectorXd residual = system.matrix * solved.x - system.target;
    const double best = 0.5 * residual.squaredNorm() - 0.5 * system.target.squaredNorm();
    line["solver"]["two_stage_s"] = ours;
    line["solver"]["projected_gradient"] = projectedGradient(system, best, 20000);
  }
  return line;
}

}  // namespace

int main(int argc, char** argv) {
  int repeat = 3, boxes = 40;
  bool gradient = true;
  std::string sizes = "640x360,1280x720,1920x1080";
  std::string writeScene;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--repeat") && i + 1 < argc)
      repeat = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--boxes") && i + 1 < argc)
      boxes = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--sizes") && i + 1 < argc)
      sizes = argv[++i];
    else if (!std::strcmp(argv[i], "--write-scene") && i + 1 < argc)
      writeScene = argv[++i];
    else if (!std::strcmp(argv[i], "--no-gradient"))
      gradient = false;
    else {
      std::cerr
          << "usage: tonemap_bench [--repeat R] [--boxes N] [--sizes WxH,...] [--no-gradient]\n";
      return 1;
    }
  }
  std::stringstream list(sizes);
  std::string size;
  while (std::getline(list, size, ',')) {
    int width = 0, height = 0;
    if (std::sscanf(size.c_str(), "%dx%d", &width, &height) != 2) return 1;
    if (!writeScene.empty()) {
      const testing::HdrScene scene = testing::roomView(width, height, boxes);
      writeRgbExr(std::filesystem::path(writeScene) / "room.exr", scene.hdr);
      writeFaceIdExr(std::filesystem::path(writeScene) / "room.faceid.exr", scene.faces);
      return 0;
    }
    std::fflush(stdout);
    const pid_t child = fork();
    if (child == 0) {
      std::cout << benchSize(width, height, boxes, std::max(1, repeat), gradient).dump()
                << std::endl;
      _exit(0);
    }
    int status = 0;
    waitpid(child, &status, 0);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return 1;
  }
  return 0;
}
