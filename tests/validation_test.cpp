// CIE 171:2006 analytical test cases (tests/validation/cie171): each scene loaded from its file,
// evaluated by the kernel, compared point by point with the exact E in the CSV beside it.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>

#include "engine/illuminance_engine.hpp"
#include "grid/grid_evaluation.hpp"
#include "scene/scene_loader.hpp"
#include "test_device.hpp"

namespace penumbra {
namespace {

const std::string kValidationDir = PENUMBRA_SOURCE_DIR "/tests/validation/cie171";
// Exact method in float: 1e-5 of the largest value of the case (points in umbra have E = 0,
// so a relative criterion per point would be undefined there).
constexpr double kRelativeToCaseMaximum = 1e-5;

using penumbra::testing::cpuDevice;

struct ExactValue {
  std::string grid;
  Vec3 position;
  double e = 0.0;
};

std::vector<ExactValue> readExact(const std::string& path) {
  std::ifstream in(path);
  std::vector<ExactValue> values;
  std::string line;
  std::getline(in, line);  // header: grid,x_m,y_m,z_m,nx,ny,nz,E_exact_lx
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::stringstream row(line);
    std::string cell;
    std::vector<std::string> cells;
    while (std::getline(row, cell, ',')) cells.push_back(cell);
    if (cells.size() < 8) continue;
    values.push_back({cells[0], Vec3(std::stod(cells[1]), std::stod(cells[2]), std::stod(cells[3])),
                      std::stod(cells[7])});
  }
  return values;
}

class Cie171 : public ::testing::TestWithParam<std::string> {};

TEST_P(Cie171, KernelMatchesTheExactValues) {
  const std::string name = GetParam();
  const Scene scene = loadScene(kValidationDir + "/" + name + ".yaml");
  const std::vector<ExactValue> exact = readExact(kValidationDir + "/" + name + ".csv");
  ASSERT_FALSE(exact.empty());
  double maximum = 0.0;
  for (const ExactValue& v : exact) maximum = std::max(maximum, v.e);

  IlluminanceEngine engine(cpuDevice(), scene);
  std::map<std::string, GridEvaluation> results;
  for (const CalculationGrid& grid : scene.grids)
    results[grid.name] = evaluateGrid(
        scene, grid, [&](std::span<const SamplePoint> p) { return engine.illuminance(p); }, 4096);

  std::map<std::string, std::size_t> next;
  double worst = 0.0;
  for (const ExactValue& v : exact) {
    ASSERT_TRUE(results.count(v.grid)) << "no grid " << v.grid;
    const GridEvaluation& r = results[v.grid];
    const std::size_t i = next[v.grid]++;
    ASSERT_LT(i, r.illuminance.size());
    ASSERT_LT((r.samples.points[i].position - v.position).norm(), 1e-9);
    const double error = std::abs(r.illuminance[i] - v.e);
    worst = std::max(worst, error / maximum);
    EXPECT_LE(error, kRelativeToCaseMaximum * maximum)
        << name << " " << v.grid << " point " << v.position.transpose()
        << ": E = " << r.illuminance[i] << " lx, exact " << v.e << " lx";
  }
  std::printf("  %s: %zu points, max |E - E_exact| = %.2e of the case maximum (%.3f lx)\n",
              name.c_str(), exact.size(), worst, maximum);
}

INSTANTIATE_TEST_SUITE_P(Validation, Cie171,
                         ::testing::Values("tc5.3", "tc5.6", "tc5.7", "tc5.11",
                                           "tc-point-isotropic", "tc-point-directional"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (char& c : n)
                             if (c == '.' || c == '-') c = '_';
                           return n;
                         });

}  // namespace
}  // namespace penumbra
