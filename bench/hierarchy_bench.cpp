// The hierarchical transfer's cost against the element count: empty square halls 3 m high, one
// 0.6 m ceiling panel of 3000 lm per 5 × 5 m bay, every surface ρ = 0.5, elements of 0.5 m, from
// about 10³ to 10⁵ elements. Each hall is solved in a child process of its own, so that its peak
// memory is its own; the bench prints elements, links, seconds per phase, the peak memory and
// the slopes of the total time, of the transfer's time and of the memory against the element
// count between successive halls, and the same halls' dense transfer where it fits
// (MeshOptions::maxElements). The mesh phase includes the direct light at every quadrature node
// from every panel, nodes × panels kernel evaluations: the panels grow with the floor, so that
// part grows with the square of the element count, as the direct light on any grid of the hall
// would.
//   usage: hierarchy_bench [--sides 10,20,40,70,110] [--link-error 2e-3] [--device cpu|gpu|N]
// Run from the repository root; POCL_MAX_PTHREAD_COUNT=2 pins PoCL to two threads.
#include <fmt/format.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cl/device.hpp"
#include "engine/illuminance_engine.hpp"
#include "radiosity/interreflection.hpp"
#include "scene/scene_loader.hpp"
#include "timing/seconds_since.hpp"

namespace {

using namespace penumbra;
namespace fs = std::filesystem;

struct HallResult {
  double elements = 0, links = 0, meshSeconds = 0, transferSeconds = 0, solveSeconds = 0;
  double totalSeconds = 0, peakMegabytes = 0;
};

// A hall `side` m square, with a panel in the middle of every 5 m bay.
fs::path writeHall(double side) {
  const fs::path file = fs::temp_directory_path() / fmt::format("hierarchy-hall-{}.yaml", side);
  std::ofstream out(file);
  out << "penumbra: 1\nmaterials:\n  paint: 0.5\nroom:\n  size: [" << side << ", " << side
      << ", 3]\n  materials: {floor: paint, ceiling: paint, walls: paint}\nsources:\n";
  const int bays = std::max(1, static_cast<int>(side / 5.0));
  const double bay = side / bays;
  for (int i = 0; i < bays; ++i)
    for (int j = 0; j < bays; ++j)
      out << fmt::format(
          "  - {{name: p{}-{}, rect: {{center: [{}, {}, 2.99], size: [0.6, 0.6], normal: [0, 0, "
          "-1]}}, flux: 3000}}\n",
          i, j, (i + 0.5) * bay, (j + 0.5) * bay);
  return file;
}

HallResult solveScene(const std::string& device, const fs::path& file, const MeshOptions& mesh) {
  const Scene scene = loadScene(file);
  compute::Device d = compute::Device::select(device);
  const auto start = Clock::now();
  IlluminanceEngine direct(d, scene);
  const Interreflection solved(d, scene, direct, mesh);
  const InterreflectionReport& r = solved.report();
  HallResult result;
  result.elements = static_cast<double>(r.elements);
  result.links = static_cast<double>(r.links);
  result.meshSeconds = r.meshSeconds;
  result.transferSeconds = r.transferSeconds;
  result.solveSeconds = r.solveSeconds;
  result.totalSeconds = secondsSince(start);
  return result;
}

// solveScene in a child process: its result through a pipe, its peak memory from wait4.
bool solveInChild(const std::string& device, const fs::path& file, const MeshOptions& mesh,
                  HallResult& result) {
  int pipeEnds[2];
  if (pipe(pipeEnds) != 0) return false;
  const pid_t child = fork();
  if (child == 0) {
    close(pipeEnds[0]);
    HallResult r;
    try {
      r = solveScene(device, file, mesh);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", file.string().c_str(), e.what());
      _exit(1);
    }
    const ssize_t written = write(pipeEnds[1], &r, sizeof r);
    _exit(written == static_cast<ssize_t>(sizeof r) ? 0 : 1);
  }
  close(pipeEnds[1]);
  const bool read_ok = read(pipeEnds[0], &result, sizeof result) == sizeof result;
  close(pipeEnds[0]);
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  result.peakMegabytes = usage.ru_maxrss / 1024.0;
  return read_ok && WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::vector<double> parseList(const std::string& text) {
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) values.push_back(std::stod(item));
  return values;
}

void printRows(const std::string& title, const std::vector<HallResult>& rows,
               const std::vector<std::string>& labels) {
  fmt::print("\n{}\n", title);
  fmt::print("{:>8} {:>9} {:>11} {:>8} {:>11} {:>8} {:>8} {:>10} {:>11} {:>14} {:>12}\n", "scene",
             "elements", "links", "mesh [s]", "transfer [s]", "solve [s]", "total [s]", "peak [MB]",
             "time slope", "transfer slope", "memory slope");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const HallResult& r = rows[i];
    std::string slopes = fmt::format("{:>11} {:>14} {:>12}", "-", "-", "-");
    if (i > 0 && rows[i - 1].elements > 0 && r.elements > rows[i - 1].elements) {
      const HallResult& before = rows[i - 1];
      const double n = std::log(r.elements / before.elements);
      slopes = fmt::format("{:>11.2f} {:>14.2f} {:>12.2f}",
                           std::log(r.totalSeconds / before.totalSeconds) / n,
                           std::log(r.transferSeconds / before.transferSeconds) / n,
                           std::log(r.peakMegabytes / before.peakMegabytes) / n);
    }
    fmt::print("{:>8} {:>9.0f} {:>11.0f} {:>8.2f} {:>11.2f} {:>8.3f} {:>8.2f} {:>10.0f} {}\n",
               labels[i], r.elements, r.links, r.meshSeconds, r.transferSeconds, r.solveSeconds,
               r.totalSeconds, r.peakMegabytes, slopes);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string device = "cpu";
  std::vector<double> sides = {10, 20, 40, 70, 110};
  std::string sceneFile, transfer = "both";
  double linkError = 2e-3;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--device") device = argv[i + 1];
    if (key == "--sides") sides = parseList(argv[i + 1]);
    if (key == "--scene") sceneFile = argv[i + 1];
    if (key == "--transfer") transfer = argv[i + 1];
    if (key == "--link-error") linkError = std::stod(argv[i + 1]);
  }
  // The scenes: the given one, or the halls (labelled by their side in m).
  std::vector<fs::path> files;
  std::vector<std::string> labels;
  if (!sceneFile.empty()) {
    files.push_back(sceneFile);
    labels.push_back(fs::path(sceneFile).stem().string());
  } else {
    for (double side : sides) {
      files.push_back(writeHall(side));
      labels.push_back(fmt::format("{:g} m", side));
    }
  }
  MeshOptions hierarchical;
  hierarchical.linkError = linkError;
  std::vector<HallResult> rows, denseRows;
  std::vector<std::string> denseLabels;
  for (std::size_t i = 0; i < files.size(); ++i) {
    HallResult r;
    if (transfer != "dense") {
      if (!solveInChild(device, files[i], hierarchical, r)) return 1;
      rows.push_back(r);
    }
    MeshOptions dense;
    if (transfer != "hierarchical" && r.elements <= static_cast<double>(dense.maxElements)) {
      HallResult d;
      if (solveInChild(device, files[i], dense, d)) {
        denseRows.push_back(d);
        denseLabels.push_back(labels[i]);
      }
    }
  }
  if (!rows.empty())
    printRows(fmt::format("Hierarchical transfer, link error {:g} (elements of 0.5 m)", linkError),
              rows, labels);
  printRows("Dense transfer, where it fits (8 000 elements)", denseRows, denseLabels);
  return 0;
}
