// Cases per second of a sweep: `penumbra sweep` on a study, which builds the OpenCL
// program once and keeps the device for every case, against `penumbra grid` run once per case as
// separate processes (program build and device set-up each time; PoCL's kernel cache is warm for
// both). Both compute the same grids of the same cases into fresh folders; each is timed
// `--repeat` times and the median is reported. Prints one JSON line and a sentence.
//   usage: sweep_bench [--study studies/window-width.yaml] [--binary build/penumbra]
//                      [--device cpu|gpu|N] [--repeat R]
// Run from the repository root; POCL_MAX_PTHREAD_COUNT=2 pins PoCL to two threads.
#include <fmt/format.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/median.hpp"
#include "study/study_cases.hpp"
#include "study/study_reader.hpp"

namespace {

namespace fs = std::filesystem;
using penumbra::Study;
using penumbra::StudyCase;

struct Options {
  fs::path study = "studies/window-width.yaml";
  fs::path binary;
  std::string device = "cpu";
  int repeat = 3;
};

// The penumbra beside this executable (both are built into the same folder).
fs::path defaultBinary() {
  return fs::read_symlink("/proc/self/exe").parent_path() / "penumbra";
}

Options parseOptions(int argc, char** argv) {
  Options options;
  options.binary = defaultBinary();
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const std::string value = argv[i + 1];
    if (key == "--study")
      options.study = value;
    else if (key == "--binary")
      options.binary = value;
    else if (key == "--device")
      options.device = value;
    else if (key == "--repeat")
      options.repeat = std::max(1, std::stoi(value));
    else
      throw std::invalid_argument("unknown option " + key);
  }
  return options;
}

std::string quoted(const fs::path& path) {
  return fmt::format("'{}'", path.string());
}

void runOrThrow(const std::string& command) {
  if (std::system(command.c_str()) != 0) throw std::runtime_error("failed: " + command);
}

double timed(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

using penumbra::bench::median;

// `penumbra grid` on one case: the same scene, values and grids as the sweep computes.
std::string gridCommand(const Options& options, const Study& study, const StudyCase& c,
                        const fs::path& out) {
  std::string command = quoted(options.binary) + " grid " + quoted(study.scene) + " -q --device " +
                        options.device + " -o " + quoted(out / c.id);
  for (const penumbra::ParameterValue& p : c.values) {
    command += " --set " + p.name + "=" + fmt::format("{}", p.value);
  }
  for (const std::string& grid : study.grids) command += " --grid " + quoted(fs::path(grid));
  return command;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = parseOptions(argc, argv);
    const Study study = penumbra::loadStudy(options.study);
    const std::vector<StudyCase> cases = penumbra::studyCases(study);
    const fs::path scratch =
        fs::temp_directory_path() / ("penumbra-sweep-bench-" + std::to_string(::getpid()));
    fs::remove_all(scratch);
    // Warm PoCL's kernel cache, so that neither side pays the first compile.
    runOrThrow(gridCommand(options, study, cases.front(), scratch / "warm-up"));

    std::vector<double> sweepSeconds, processSeconds;
    for (int r = 0; r < options.repeat; ++r) {
      const fs::path sweepOut = scratch / ("sweep-" + std::to_string(r));
      sweepSeconds.push_back(timed([&] {
        runOrThrow(quoted(options.binary) + " sweep " + quoted(options.study) + " -q --device " +
                   options.device + " -o " + quoted(sweepOut));
      }));
      const fs::path gridOut = scratch / ("grid-" + std::to_string(r));
      processSeconds.push_back(timed([&] {
        for (const StudyCase& c : cases) runOrThrow(gridCommand(options, study, c, gridOut));
      }));
    }
    fs::remove_all(scratch);

    const double n = static_cast<double>(cases.size());
    const double sweepRate = n / median(sweepSeconds);
    const double processRate = n / median(processSeconds);
    nlohmann::json line = {
        {"study", options.study.string()}, {"cases", cases.size()},
        {"device", options.device},        {"repeat", options.repeat},
        {"sweep_s", median(sweepSeconds)}, {"processes_s", median(processSeconds)},
        {"sweep_cases_per_s", sweepRate},  {"processes_cases_per_s", processRate},
        {"ratio", sweepRate / processRate}};
    std::cout << line.dump() << "\n";
    std::cout << fmt::format(
        "{} cases: penumbra sweep {:.1f} cases/s, one penumbra grid per case {:.1f} cases/s: "
        "{:.1f}x\n",
        cases.size(), sweepRate, processRate, sweepRate / processRate);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "sweep_bench: " << e.what() << "\n";
    return 1;
  }
}
