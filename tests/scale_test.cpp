// Scale without surprise (docs/reliability.md, "Scale"): the solid index gives the answers of
// testing every solid, a planar grid is described rather than stored, host memory does not grow
// with the number of grid points, and a request the device cannot hold either shrinks to fit or
// stops with a clear message and no output.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "geometry/tolerance.hpp"
#include "grid/grid_evaluation.hpp"
#include "penumbra_process.hpp"
#include "sanitized_build.hpp"
#include "scene/scene_loader.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using testing::readText;
using testing::TempDir;

// ------------------------------------------------------------------ the solid index

// What SolidLocator replaces: every solid tested in scene order.
int classifyByEverySolid(const Scene& scene, SamplePoint& point) {
  const double tolerance = Tolerance::kRelativeInput * std::max(scene.size(), 1.0);
  int inside = -1;
  double bestAlignment = -2.0;
  point.solid = -1;
  for (int s = 0; s < static_cast<int>(scene.solids.size()); ++s) {
    const ConvexPolyhedron& shape = scene.solids[s].shape;
    if (shape.empty()) continue;
    const int face = shape.faceContaining(point.position, point.normal, tolerance);
    if (face >= 0) {
      const double alignment = shape.faces()[face].plane.normal.dot(point.normal);
      if (alignment > bestAlignment) {
        bestAlignment = alignment;
        point.solid = s;
      }
    }
    if (inside < 0 && shape.containsStrictly(point.position, tolerance)) inside = s;
  }
  return inside;
}

TEST(SolidLocator, GivesTheAnswersOfTestingEverySolid) {
  std::mt19937_64 random(10);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Scene scene;
  // A floor and a wall spanning the scene, 300 small boxes (some touching, some overlapping)
  // and 40 thin slanted hulls (small inner radius: their boxes are grown the most).
  scene.solids.push_back({"floor", ConvexPolyhedron::box({0, 0, -0.2}, {10, 10, 0}), -1});
  scene.solids.push_back({"wall", ConvexPolyhedron::box({-0.2, 0, 0}, {0, 10, 3}), -1});
  for (int i = 0; i < 300; ++i) {
    const Vec3 lo(9.5 * unit(random), 9.5 * unit(random), i % 3 == 0 ? 0.0 : 2.5 * unit(random));
    const Vec3 size(0.05 + 0.4 * unit(random), 0.05 + 0.4 * unit(random),
                    0.05 + 0.4 * unit(random));
    scene.solids.push_back({fmt::format("box{}", i), ConvexPolyhedron::box(lo, lo + size), -1});
  }
  for (int i = 0; i < 40; ++i) {
    const Vec3 a(9 * unit(random), 9 * unit(random), 2.5 * unit(random));
    const Vec3 d(0.5 + unit(random), 0.3 * unit(random), 0.2 * unit(random));
    const Vec3 t(0.0, 0.0, 1e-3 + 0.01 * unit(random));  // thickness 1 to 11 mm
    scene.solids.push_back(
        {fmt::format("slab{}", i),
         ConvexPolyhedron::hull({a, a + d, a + Vec3(0, 0.4, 0), a + d + Vec3(0, 0.4, 0), a + t,
                                 a + d + t, a + Vec3(0, 0.4, 0) + t, a + d + Vec3(0, 0.4, 0) + t},
                                1e-9),
         -1});
  }
  const SolidLocator locator(scene);
  // Points anywhere, on faces (a face's vertex average, nudged within and beyond the input
  // tolerance), at vertices, and just outside the scene.
  std::vector<SamplePoint> points;
  const Vec3 normals[] = {Vec3::UnitZ(), -Vec3::UnitZ(), Vec3::UnitX(), Vec3(1, 1, 1).normalized()};
  for (int i = 0; i < 4000; ++i) {
    points.push_back(
        {Vec3(11 * unit(random) - 0.5, 11 * unit(random) - 0.5, 3.6 * unit(random) - 0.3),
         normals[i % 4], -1});
  }
  for (const Solid& solid : scene.solids) {
    for (const auto& face : solid.shape.faces()) {
      Vec3 centre = Vec3::Zero();
      for (int v : face.vertices) centre += solid.shape.vertices()[v];
      centre /= static_cast<double>(face.vertices.size());
      for (double nudge : {0.0, 5e-6, -5e-6, 2e-5, -2e-5})
        points.push_back({centre + nudge * face.plane.normal, face.plane.normal, -1});
    }
    for (const Vec3& v : solid.shape.vertices()) points.push_back({v, Vec3::UnitZ(), -1});
  }
  int onSolids = 0, insideSolids = 0;
  for (SamplePoint expected : points) {
    SamplePoint indexed = expected;
    const int insideExpected = classifyByEverySolid(scene, expected);
    const int insideIndexed = locator.classify(indexed);
    ASSERT_EQ(insideIndexed, insideExpected) << expected.position.transpose();
    ASSERT_EQ(indexed.solid, expected.solid) << expected.position.transpose();
    onSolids += expected.solid >= 0;
    insideSolids += insideExpected >= 0;
  }
  // The sample reaches every case.
  EXPECT_GT(onSolids, 1000);
  EXPECT_GT(insideSolids, 500);
}

// ------------------------------------------------------------------ planar grids

TEST(PlanarGrid, PointsComeFromTheFrameAndTheSceneBoxFromTheCorners) {
  const Vec3 origin(0.3, -1.7, 0.85), u(2.9, 0.7, 0.0), v(-0.35, 1.45, 0.4);
  const CalculationGrid grid =
      CalculationGrid::planar("g", GridKind::Rect, origin, u, v, 37, 23, 0.1);
  ASSERT_EQ(grid.size(), 37u * 23u);
  Scene scene;
  scene.grids.push_back(grid);
  BoundingBox all;
  for (int r = 0; r < 23; ++r) {
    for (int c = 0; c < 37; ++c) {
      const std::size_t i = static_cast<std::size_t>(r) * 37 + c;
      const Vec3 expected = origin + (c + 0.5) / 37 * u + (r + 0.5) / 23 * v;
      EXPECT_EQ(grid.position(i), expected) << i;
      EXPECT_TRUE(grid.normal(i).isApprox(u.cross(v).normalized(), 1e-15));
      all.add(expected);
    }
  }
  EXPECT_EQ(scene.size(), (all.hi - all.lo).norm());
}

// ------------------------------------------------------------------ the command line

// One panel over a 6 × 4 m floor (in a room, or alone), a rect grid at `spacing`.
std::string panelScene(double spacing, bool room) {
  return fmt::format(R"(penumbra: 1
{}sources:
  - {{name: p, rect: {{center: [3, 2, 2.99], size: [0.6, 0.6], normal: [0, 0, -1]}}, flux: 3000}}
grids:
  - {{name: floor, rect: {{origin: [0, 0, 0], u: [6, 0, 0], v: [0, 4, 0]}}, spacing: {}}}
)",
                     room ? "room: {size: [6, 4, 3]}\n" : "", spacing);
}

void write(const fs::path& file, const std::string& text) {
  std::ofstream(file) << text;
}

struct Measured {
  int status = -1;
  long maxRssKb = 0;  // the child's peak resident set
  std::string err;
};

// Runs penumbra in `dir` with `arguments`, and PENUMBRA_DEVICE_MEMORY=`deviceMemory` when not
// empty; the peak RSS comes from wait4, for this child alone.
Measured runMeasured(const fs::path& dir, std::vector<std::string> arguments,
                     const std::string& deviceMemory = "") {
  arguments.insert(arguments.begin(), PENUMBRA_BINARY);
  std::vector<char*> argv;
  for (std::string& a : arguments) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env;
  for (char** e = environ; *e != nullptr; ++e) {
    if (!std::string(*e).starts_with("PENUMBRA_DEVICE_MEMORY=")) env.emplace_back(*e);
  }
  if (!deviceMemory.empty()) env.push_back("PENUMBRA_DEVICE_MEMORY=" + deviceMemory);
  if (testing::kSanitizedBuild) {
    // ASan keeps freed blocks in a quarantine of up to 256 MB, so a sanitized run's peak RSS grows
    // with everything it ever allocated (measured: 210 bytes a point from 2e5 to 1e6). Without the
    // quarantine the peak follows what is alive, which is what this measures (the rest of ASan's
    // checks stay on).
    auto asan = std::find_if(env.begin(), env.end(),
                             [](const std::string& e) { return e.starts_with("ASAN_OPTIONS="); });
    if (asan == env.end()) asan = env.insert(env.end(), "ASAN_OPTIONS=");
    *asan += ":quarantine_size_mb=0:thread_local_quarantine_size_kb=0";
  }
  std::vector<char*> envp;
  for (std::string& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  const fs::path errFile = dir / "stderr.txt";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, errFile.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const fs::path previous = fs::current_path();
  fs::current_path(dir);
  pid_t pid = -1;
  const int spawned =
      posix_spawn(&pid, PENUMBRA_BINARY, &actions, nullptr, argv.data(), envp.data());
  fs::current_path(previous);
  posix_spawn_file_actions_destroy(&actions);
  Measured m;
  if (spawned != 0) return m;
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  m.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  m.maxRssKb = usage.ru_maxrss;
  m.err = readText(errFile);
  fs::remove(errFile);
  return m;
}

std::vector<std::string> gridRun(const std::string& output) {
  return {"grid", "scene.yaml", "-o", output, "--device", "cpu", "-q"};
}

// Nothing named like the output or its staging folder is left in `dir`.
void expectNoOutput(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(name == "scene.yaml") << "left behind: " << name;
  }
}

TEST(DeviceMemory, ASceneTooLargeForTheDeviceStopsWithItsNumbersAndNoOutput) {
  TempDir dir("penumbra-scale");
  write(dir.path() / "scene.yaml", panelScene(0.5, true));
  // 64 KB of device memory: the room's six slabs fit, and no table may exceed 32 bytes.
  const Measured run = runMeasured(dir.path(), gridRun("out"), "64K,32");
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_NE(run.err.find("penumbra: error: the scene (source faces: 1, occluders: "),
            std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("of global memory and allows 32 bytes in one buffer: use a smaller scene"),
            std::string::npos)
      << run.err;
  EXPECT_EQ(run.err.find("Abort"), std::string::npos);
  expectNoOutput(dir.path());
}

TEST(DeviceMemory, BatchesShrinkToFitAndGiveTheSameValues) {
  TempDir dir("penumbra-scale");
  write(dir.path() / "scene.yaml", panelScene(0.04, true));  // 150 × 100 points
  const Measured full = runMeasured(dir.path(), gridRun("full"));
  ASSERT_EQ(full.status, 0) << full.err;
  // A batch of 15 000 points needs about 0.6 MB on the device (coordinates, classes, patch
  // table); 256 KB holds a few thousand at a time.
  const Measured small = runMeasured(dir.path(), gridRun("small"), "256K");
  ASSERT_EQ(small.status, 0) << small.err;
  for (const char* file : {"floor.res", "floor.csv"}) {
    EXPECT_EQ(readText(dir.path() / "small" / file), readText(dir.path() / "full" / file)) << file;
  }
}

TEST(DeviceMemory, ABatchThatCannotShrinkEnoughStopsWithItsNumbersAndNoOutput) {
  TempDir dir("penumbra-scale");
  write(dir.path() / "scene.yaml", panelScene(0.5, false));  // no solids: a tiny scene table
  // One buffer may hold 256 bytes: the scene's (one face, four vertices) fit, but even the
  // smallest batch (128 points: 512 bytes of x coordinates) does not.
  const Measured run = runMeasured(dir.path(), gridRun("sub/out"), "1G,256");
  EXPECT_EQ(run.status, 1) << run.err;
  EXPECT_NE(run.err.find("penumbra: error: a batch of 96 points needs "), std::string::npos)
      << run.err;
  EXPECT_NE(run.err.find("even the smallest batch does not fit beside the scene"),
            std::string::npos)
      << run.err;
  expectNoOutput(dir.path());
}

TEST(DeviceMemory, AMalformedLimitIsNamed) {
  TempDir dir("penumbra-scale");
  write(dir.path() / "scene.yaml", panelScene(0.5, false));
  const Measured run = runMeasured(dir.path(), gridRun("out"), "lots");
  EXPECT_EQ(run.status, 1);
  EXPECT_NE(run.err.find("PENUMBRA_DEVICE_MEMORY='lots'"), std::string::npos) << run.err;
  expectNoOutput(dir.path());
}

// Host memory is bounded by the batch (65 536 points), not by the grid: from 2·10^5 to 10^6
// points the peak RSS may grow by less than 16 bytes a point (12.8 MB in all; measured: under
// 2 MB, the allocator's and PoCL's noise). Holding any per-point record would break it: the
// points as SamplePoint are 56 bytes, the grid's positions and normals 48, and a grid evaluated
// whole rather than streamed holds 214 a point. (Keeping only E, 8 bytes, would pass: it is the
// output.)
// Under ASan the peak varies by about ±12 MB from run to run (five runs over 8·10^5 points: -15 to
// +22 bytes a point), so the sanitizer build's large grid has 3·10^6 points: the same bound per
// point, 45 MB in all, the noise a quarter of it.
TEST(HostMemory, PeakRssDoesNotGrowWithThePoints) {
  TempDir dir("penumbra-scale");
  const double largePoints = testing::kSanitizedBuild ? 3e6 : 1e6;
  const double smallSpacing = std::sqrt(24.0 / 2e5), largeSpacing = std::sqrt(24.0 / largePoints);
  write(dir.path() / "scene.yaml", panelScene(smallSpacing, true));
  const Measured small = runMeasured(dir.path(), gridRun("small"));
  ASSERT_EQ(small.status, 0) << small.err;
  write(dir.path() / "scene.yaml", panelScene(largeSpacing, true));
  const Measured large = runMeasured(dir.path(), gridRun("large"));
  ASSERT_EQ(large.status, 0) << large.err;
  const double points = largePoints - 2e5;
  const double perPoint = (large.maxRssKb - small.maxRssKb) * 1024.0 / points;
  std::printf("peak RSS: %ld kB at 2e5 points, %ld kB at %.0e: %.2f bytes a point\n",
              small.maxRssKb, large.maxRssKb, largePoints, perPoint);
  EXPECT_LT(perPoint, 16.0);
  // The grid's rows and columns: ceil(6 m and 4 m over the spacing).
  EXPECT_EQ(testing::lines(readText(dir.path() / "large" / "floor.res")).size(),
            testing::kSanitizedBuild ? 2122u * 1415u : 1225u * 817u);
}

}  // namespace
}  // namespace penumbra
