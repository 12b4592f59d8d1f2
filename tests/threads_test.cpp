// The kernel's result does not depend on how many threads PoCL runs (within 1e-6 relative): the
// example office is computed by the `penumbra` binary once with POCL_MAX_PTHREAD_COUNT=1 and once
// with 2 (the variable is read when PoCL starts, hence separate processes). Two runs alike write
// the same bytes (determinism).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

std::vector<double> readRes(const fs::path& file) {
  std::ifstream in(file);
  std::vector<double> values;
  for (double v; in >> v;) values.push_back(v);
  return values;
}

std::string readBytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

fs::path runWithThreads(int threads, const std::string& tag = "") {
  const fs::path out =
      fs::temp_directory_path() /
      ("penumbra-threads-" + std::to_string(::getpid()) + "-" + std::to_string(threads) + tag);
  fs::remove_all(out);
  const std::string command = "POCL_MAX_PTHREAD_COUNT=" + std::to_string(threads) + " \"" +
                              PENUMBRA_BINARY + "\" grid \"" + PENUMBRA_SOURCE_DIR +
                              "/data/office.yaml\" --device cpu --quiet -o \"" + out.string() +
                              "\" > /dev/null";
  EXPECT_EQ(std::system(command.c_str()), 0) << command;
  return out;
}

TEST(PoclThreads, OneAndTwoThreadsGiveTheSameIlluminance) {
  const fs::path one = runWithThreads(1), two = runWithThreads(2);
  int grids = 0;
  for (const auto& entry : fs::directory_iterator(one)) {
    if (entry.path().extension() != ".res") continue;
    ++grids;
    const std::vector<double> a = readRes(entry.path());
    const std::vector<double> b = readRes(two / entry.path().filename());
    ASSERT_EQ(a.size(), b.size()) << entry.path();
    ASSERT_FALSE(a.empty());
    for (std::size_t i = 0; i < a.size(); ++i)
      EXPECT_NEAR(a[i], b[i], 1e-6 * std::abs(a[i])) << entry.path().filename() << " point " << i;
  }
  EXPECT_GE(grids, 3);
  fs::remove_all(one);
  fs::remove_all(two);
}

// Every grid file (.csv with points and E, .res) byte for byte; summary.json holds timings.
TEST(PoclThreads, TwoRunsWriteTheSameGridFiles) {
  const fs::path first = runWithThreads(2, "-first"), second = runWithThreads(2, "-second");
  int files = 0;
  for (const auto& entry : fs::directory_iterator(first)) {
    const std::string extension = entry.path().extension().string();
    if (extension != ".res" && extension != ".csv") continue;
    ++files;
    const std::string bytes = readBytes(entry.path());
    ASSERT_FALSE(bytes.empty()) << entry.path();
    EXPECT_TRUE(bytes == readBytes(second / entry.path().filename())) << entry.path().filename();
  }
  EXPECT_GE(files, 6);
  fs::remove_all(first);
  fs::remove_all(second);
}

}  // namespace
