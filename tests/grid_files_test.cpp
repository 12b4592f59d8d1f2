// The text of the result files and the streamed grid behind them: numbers written straight into
// buffers read back to the same doubles and are the text fmt::format("{}") gives; rows, and whole
// files written batch by batch on the writer's thread, are those of the plain fmt formatting;
// classifying points ahead of the batches changes neither the batches nor the answers.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_files.hpp"

#include "grid/grid_evaluation.hpp"
#include "output/grid_file_writer.hpp"
#include "output/grid_rows.hpp"
#include "output/number_text.hpp"
#include "output/result_files.hpp"

namespace penumbra {
namespace {

using penumbra::testing::readText;
using penumbra::testing::TempDir;

std::string written(double value) {
  char text[kMaxNumberText];
  return std::string(text, writeNumber(text, value));
}

std::string cached(NumberTextCache& cache, double value) {
  char text[kMaxNumberText];
  return std::string(text, cache.write(text, value));
}

// Edge cases, then random bit patterns (every exponent) and random values of a room's scale.
std::vector<double> testValues() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<double> values = {0.0,
                                -0.0,
                                1.0,
                                -1.0,
                                0.1,
                                1e-30,
                                -1e-30,
                                1e-5,
                                1e-4,
                                123456.0,
                                1e15,
                                1e16,
                                1e300,
                                2.5500000000000003,
                                1006.5396118164062,
                                std::numeric_limits<double>::denorm_min(),
                                -std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::min(),
                                std::nextafter(std::numeric_limits<double>::min(), 0.0),
                                std::numeric_limits<double>::max(),
                                -std::numeric_limits<double>::max(),
                                std::numeric_limits<double>::epsilon(),
                                static_cast<double>(std::numeric_limits<float>::max()),
                                static_cast<double>(std::numeric_limits<float>::denorm_min()),
                                inf,
                                -inf};
  std::mt19937_64 random(2024);
  for (int k = 0; k < 200000; ++k) {
    const double v = std::bit_cast<double>(random());
    if (std::isfinite(v)) values.push_back(v);
  }
  std::uniform_real_distribution<double> metres(-50.0, 50.0);
  for (int k = 0; k < 100000; ++k) values.push_back(metres(random));
  for (int k = 0; k < 100000; ++k) values.push_back(static_cast<float>(metres(random) * 100.0));
  return values;
}

TEST(NumberText, ReadsBackToTheSameDoubleAndIsFmtsText) {
  NumberTextCache cache;
  for (const double v : testValues()) {
    const std::string text = written(v);
    ASSERT_LE(text.size(), 24u) << text;
    ASSERT_EQ(text, fmt::format("{}", v));
    ASSERT_EQ(cached(cache, v), text);
    if (std::isfinite(v)) {
      const double back = std::strtod(text.c_str(), nullptr);
      ASSERT_EQ(std::bit_cast<std::uint64_t>(back), std::bit_cast<std::uint64_t>(v)) << text;
    }
  }
  EXPECT_EQ(written(std::numeric_limits<double>::quiet_NaN()), "nan");
}

TEST(NumberText, TheCacheGivesEachValueItsOwnTextWhenValuesShareASlot) {
  // Far more distinct values than slots, each asked for several times in a shuffled order: every
  // answer is the value's own text, whether it was kept, displaced or never kept.
  std::vector<double> values;
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> u(0.0, 12.0);
  for (int k = 0; k < 50000; ++k) values.push_back(u(random));
  values.push_back(0.0);
  values.push_back(-0.0);
  values.push_back(-1.7976931348623157e+308);  // 24 characters: written, never kept
  std::vector<double> asked;
  for (int r = 0; r < 4; ++r) asked.insert(asked.end(), values.begin(), values.end());
  std::shuffle(asked.begin(), asked.end(), random);
  NumberTextCache cache;
  for (const double v : asked) ASSERT_EQ(cached(cache, v), fmt::format("{}", v));
}

TEST(GridRows, RowsAreThoseOfThePlainFmtFormat) {
  GridRows rows(NumberDigits::Double);
  std::string csv, res, pts;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  const std::vector<std::string> fields = {"", "desk", csvField("a, \"b\""), ""};
  for (int k = 0; k < 5000; ++k) {
    const Vec3 p(u(random), 0.01 * (k / 100), 0.8);
    // Normals change now and then, to -0 and back among them (a text of its own).
    const Vec3 n = k % 7 == 0    ? Vec3(u(random), u(random), u(random)).normalized()
                   : k % 13 == 0 ? Vec3(-0.0, 0.0, 1.0)
                                 : Vec3::UnitZ();
    const double e = k % 11 == 0 ? 0.0 : std::exp(5.0 * u(random));
    const std::string& field = fields[k % fields.size()];
    rows.add(p, n, e, field);
    csv += fmt::format("{},{},{},{},{},{},{},{}\n", p.x(), p.y(), p.z(), n.x(), n.y(), n.z(), e,
                       field);
    res += fmt::format("{}\n", e);
    pts += fmt::format("{} {} {} {} {} {}\n", p.x(), p.y(), p.z(), n.x(), n.y(), n.z());
  }
  EXPECT_EQ(rows.csv(), csv);
  EXPECT_EQ(rows.res(), res);
  EXPECT_EQ(rows.pts(), pts);
  rows.clear();
  rows.addIlluminance(1e-30);
  EXPECT_EQ(rows.csv(), "");
  EXPECT_EQ(rows.res(), "1e-30\n");
}

// A floor slab with a table standing on it, and a box whose name needs quoting in a CSV.
Scene floorTableAndBox() {
  Scene scene;
  scene.solids.push_back(
      Solid{"floor", ConvexPolyhedron::box({-1.0, -1.0, -0.2}, {5.0, 5.0, 0.0}), -1});
  scene.solids.push_back(
      Solid{"table", ConvexPolyhedron::box({1.0, 1.0, 0.0}, {2.0, 2.0, 0.75}), -1});
  scene.solids.push_back(
      Solid{"box, \"tall\"", ConvexPolyhedron::box({3.0, 0.5, 0.0}, {3.5, 3.5, 2.0}), -1});
  return scene;
}

// A 4 × 4 m plane at 0.5 m through the table and the box: runs of inside points cross the
// batches and the classification blocks.
CalculationGrid plane(int side) {
  return CalculationGrid::planar("plane", GridKind::Rect, Vec3(0.0, 0.0, 0.5), Vec3(4.0, 0.0, 0.0),
                                 Vec3(0.0, 4.0, 0.0), side, side, 4.0 / side);
}

double byPosition(const SamplePoint& p) {
  return 100.0 * p.position.x() + std::sqrt(p.position.y());
}

TEST(GridFileWriter, FilesWrittenBatchByBatchAreThoseOfThePlainFmtFormat) {
  TempDir dir("penumbra-grid-files-test");
  const Scene scene = floorTableAndBox();
  const CalculationGrid grid = plane(150);  // 22 500 points
  const IlluminanceEstimator estimate = [](std::span<const SamplePoint> points) {
    std::vector<double> e;
    for (const SamplePoint& p : points) e.push_back(byPosition(p));
    return e;
  };
  GridFileWriter files(dir.path(), scene, grid, false, NumberDigits::Double);
  streamGrid(scene, grid, estimate, 1000, [&](const GridBatch& batch) { files.write(batch); });
  files.close();

  const GridSamples samples = gridSamples(scene, grid);
  std::string csv = "x_m,y_m,z_m,nx,ny,nz,E_lx,inside\n", res, pts;
  int insideBox = 0;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const Vec3 p = grid.position(i), n = grid.normal(i);
    const int in = samples.inside[i];
    const double e = in >= 0 ? 0.0 : byPosition(samples.points[i]);
    insideBox += in == 2;
    csv += fmt::format("{},{},{},{},{},{},{},{}\n", p.x(), p.y(), p.z(), n.x(), n.y(), n.z(), e,
                       in >= 0 ? csvField(scene.solids[in].name) : "");
    res += fmt::format("{}\n", e);
    pts += fmt::format("{} {} {} {} {} {}\n", p.x(), p.y(), p.z(), n.x(), n.y(), n.z());
  }
  EXPECT_GT(insideBox, 0);
  EXPECT_EQ(readText(dir.path() / "plane.csv"), csv);
  EXPECT_EQ(readText(dir.path() / "plane.res"), res);
  EXPECT_EQ(readText(dir.path() / "plane.pts"), pts);
}

TEST(GridEvaluation, ClassifyingAheadKeepsTheBatchesAndTheAnswers) {
  // Every batch is what the point-by-point rule makes of the grid: up to batchSize points
  // outside solids, with the inside points among them; a run of inside points alone goes on
  // after batchSize of them. Checked against gridSamples, which classifies one point at a time.
  const Scene scene = floorTableAndBox();
  const CalculationGrid grid = plane(211);  // 44 521 points, several blocks of 4096
  const GridSamples samples = gridSamples(scene, grid);
  for (const std::size_t batchSize : {std::size_t{1}, std::size_t{700}, std::size_t{5000}}) {
    std::vector<std::size_t> expectedSizes;
    std::size_t outside = 0, taken = 0;
    for (std::size_t i = 0; i < grid.size(); ++i) {
      outside += samples.inside[i] < 0;
      ++taken;
      if (outside == batchSize || (outside == 0 && taken >= batchSize)) {
        expectedSizes.push_back(taken);
        outside = taken = 0;
      }
    }
    if (taken > 0) expectedSizes.push_back(taken);

    std::vector<std::size_t> sizes;
    std::size_t next = 0;
    const IlluminanceEstimator estimate = [](std::span<const SamplePoint> points) {
      std::vector<double> e;
      for (const SamplePoint& p : points) e.push_back(byPosition(p));
      return e;
    };
    streamGrid(scene, grid, estimate, batchSize, [&](const GridBatch& batch) {
      ASSERT_EQ(batch.first, next);
      sizes.push_back(batch.illuminance.size());
      for (std::size_t k = 0; k < batch.illuminance.size(); ++k) {
        const std::size_t i = batch.first + k;
        ASSERT_EQ(batch.inside[k], samples.inside[i]) << i;
        ASSERT_EQ(batch.onSolid[k], samples.points[i].solid) << i;
        ASSERT_EQ(batch.illuminance[k],
                  samples.inside[i] >= 0 ? 0.0 : byPosition(samples.points[i]));
      }
      next += batch.illuminance.size();
    });
    EXPECT_EQ(next, grid.size());
    EXPECT_EQ(sizes, expectedSizes) << "batch size " << batchSize;
  }
}

TEST(GridEvaluation, TheEstimatorTakesOneBatchAtATimeInGridOrderWhileTheNextIsGathered) {
  // The next batch is classified while the estimator computes one: the estimator still sees
  // the batches one call at a time, in grid order, and the sink gets the same values in order.
  const Scene scene = floorTableAndBox();
  const CalculationGrid grid = plane(211);
  const GridSamples samples = gridSamples(scene, grid);
  std::vector<SamplePoint> outside;
  for (std::size_t i = 0; i < grid.size(); ++i)
    if (samples.inside[i] < 0) outside.push_back(samples.points[i]);
  constexpr std::size_t batchSize = 3000;
  std::atomic<int> inFlight = 0;
  int mostInFlight = 0;
  std::size_t estimated = 0;  // points the estimator has been given, in order
  const IlluminanceEstimator estimate = [&](std::span<const SamplePoint> points) {
    mostInFlight = std::max(mostInFlight, ++inFlight);
    std::vector<double> e;
    for (const SamplePoint& p : points) {
      EXPECT_EQ(p.position, outside.at(estimated).position);
      ++estimated;
      e.push_back(byPosition(p));
    }
    --inFlight;
    return e;
  };
  std::size_t next = 0;
  streamGrid(scene, grid, estimate, batchSize, [&](const GridBatch& batch) {
    ASSERT_EQ(batch.first, next);
    for (std::size_t k = 0; k < batch.illuminance.size(); ++k) {
      const std::size_t i = batch.first + k;
      ASSERT_EQ(batch.illuminance[k], samples.inside[i] >= 0 ? 0.0 : byPosition(samples.points[i]));
    }
    next += batch.illuminance.size();
  });
  EXPECT_EQ(mostInFlight, 1);
  EXPECT_EQ(estimated, outside.size());
  EXPECT_EQ(next, grid.size());
}

TEST(GridEvaluation, AnEstimatorFailureReachesTheCallerAfterTheBatchesBeforeIt) {
  const Scene scene = floorTableAndBox();
  const CalculationGrid grid = plane(211);
  int calls = 0;
  const IlluminanceEstimator estimate = [&](std::span<const SamplePoint> points) {
    if (++calls == 3) throw std::runtime_error("the device went away");
    return std::vector<double>(points.size(), 1.0);
  };
  std::size_t batches = 0;
  try {
    streamGrid(scene, grid, estimate, 3000, [&](const GridBatch&) { ++batches; });
    ADD_FAILURE() << "streamGrid returned";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "the device went away");
  }
  EXPECT_EQ(calls, 3);
  EXPECT_EQ(batches, 2u);
}

}  // namespace
}  // namespace penumbra
