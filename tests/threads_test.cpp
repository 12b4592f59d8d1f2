// The kernel's result does not depend on how many threads PoCL runs (issue 2, item 6): the
// example office is computed by the `penumbra` binary once with POCL_MAX_PTHREAD_COUNT=1 and
// once with 2 (the variable is read when PoCL starts, hence separate processes).
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

fs::path runWithThreads(int threads) {
  const fs::path out =
      fs::temp_directory_path() /
      ("penumbra-threads-" + std::to_string(::getpid()) + "-" + std::to_string(threads));
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
      EXPECT_NEAR(a[i], b[i], 1e-5 * std::abs(a[i])) << entry.path().filename() << " point " << i;
  }
  EXPECT_GE(grids, 3);
  fs::remove_all(one);
  fs::remove_all(two);
}

}  // namespace
