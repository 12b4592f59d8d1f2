// A `penumbra grid` run stopped by SIGINT (Ctrl-C) or SIGTERM (a scheduler's time limit) leaves
// nothing partial behind: no output folder, or the previous one untouched, and no
// hidden staging folder. The signal is sent while the result files are being written (the
// moment the staging folder appears), the moment where a partial file could exist.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "penumbra_process.hpp"
#include "test_files.hpp"

namespace {

namespace fs = std::filesystem;

using penumbra::testing::PenumbraProcess;
using penumbra::testing::readText;
using penumbra::testing::Result;
using penumbra::testing::runPenumbra;
using penumbra::testing::TempDir;

// One panel over an empty 6 × 4 m floor; `spacing` sets the number of points, and so how long
// the result files take to write.
std::string scene(double spacing) {
  return fmt::format(R"(penumbra: 1
room: {{size: [6, 4, 3]}}
sources:
  - {{name: p, rect: {{center: [3, 2, 2.99], size: [0.6, 0.6], normal: [0, 0, -1]}}, flux: 3000}}
grids:
  - {{name: floor, rect: {{origin: [0, 0, 0], u: [6, 0, 0], v: [0, 4, 0]}}, spacing: {}}}
)",
                     spacing);
}

void write(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

// Entries of `dir` whose names say they are staging (".…partial-…").
std::vector<std::string> stagingIn(const fs::path& dir) {
  std::vector<std::string> found;
  if (!fs::is_directory(dir)) return found;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".partial-") != std::string::npos) found.push_back(name);
  }
  return found;
}

// Every entry of `dir` by name, with its bytes (a folder's are empty).
std::map<std::string, std::string> filesIn(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(dir))
    files[entry.path().filename().string()] = readText(entry.path());
  return files;
}

std::vector<std::string> names(const std::map<std::string, std::string>& files) {
  std::vector<std::string> result;
  for (const auto& entry : files) result.push_back(entry.first);
  return result;
}

// Starts `penumbra grid scene.yaml -o out` in `dir`, waits until `staging(pid)` exists (the
// result files are being written), sends `signal`, and returns the wait status.
template <typename StagingPath>
int interruptWhileWriting(const fs::path& dir, int signal, StagingPath staging) {
  PenumbraProcess run(dir, {"grid", "scene.yaml", "-o", "out", "--device", "cpu", "-q"});
  EXPECT_TRUE(run.started());
  const fs::path seen = staging(dir, run.pid());
  while (run.running() && !fs::exists(seen))
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  EXPECT_TRUE(run.running()) << "the run finished before the test could stop it";
  return run.stop(signal);
}

class Interrupt : public ::testing::TestWithParam<int> {};

TEST_P(Interrupt, WhileWritingANewFolderLeavesNothing) {
  const int signal = GetParam();
  TempDir dir("penumbra-interrupt");
  write(dir.path() / "scene.yaml", scene(0.008));  // 750 × 500 points: writing takes a while
  const int status = interruptWhileWriting(dir.path(), signal, [](const fs::path& d, pid_t pid) {
    return d / fmt::format(".out.partial-{}", pid);
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal)
      << "the run should end by the signal it got; wait status " << status;
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
  EXPECT_TRUE(stagingIn(dir.path()).empty()) << stagingIn(dir.path()).front();
}

TEST_P(Interrupt, WhileRewritingAFolderLeavesThePreviousFilesIntact) {
  const int signal = GetParam();
  TempDir dir("penumbra-interrupt");
  // The previous results: a coarse grid of the same scene.
  write(dir.path() / "scene.yaml", scene(0.5));
  const Result first = runPenumbra(dir.path(), "grid scene.yaml -o out --device cpu -q");
  ASSERT_EQ(first.status, 0) << first.err;
  const std::map<std::string, std::string> before = filesIn(dir.path() / "out");
  ASSERT_GE(before.size(), 2u);

  write(dir.path() / "scene.yaml", scene(0.008));
  const int status = interruptWhileWriting(dir.path(), signal, [](const fs::path& d, pid_t pid) {
    return d / "out" / fmt::format(".penumbra.partial-{}", pid);
  });
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "wait status " << status;
  const std::map<std::string, std::string> after = filesIn(dir.path() / "out");
  EXPECT_EQ(names(after), names(before));  // no staging folder inside
  for (const auto& [name, bytes] : before) {
    EXPECT_TRUE(after.count(name) && after.at(name) == bytes) << name << " changed";
  }
  EXPECT_TRUE(stagingIn(dir.path()).empty());
}

TEST_P(Interrupt, WhileComputingLeavesNothing) {
  const int signal = GetParam();
  TempDir dir("penumbra-interrupt");
  write(dir.path() / "scene.yaml", scene(0.004));  // 1500 × 1000 points: still computing at 300 ms
  PenumbraProcess run(dir.path(), {"grid", "scene.yaml", "-o", "sub/out", "--device", "cpu", "-q"});
  ASSERT_TRUE(run.started());
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_TRUE(run.running()) << "the run finished before the test could stop it";
  const int status = run.stop(signal);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == signal) << "wait status " << status;
  EXPECT_FALSE(fs::exists(dir.path() / "sub"));
}

INSTANTIATE_TEST_SUITE_P(Signals, Interrupt, ::testing::Values(SIGINT, SIGTERM),
                         [](const auto& info) {
                           return info.param == SIGINT ? "SIGINT" : "SIGTERM";
                         });

}  // namespace
