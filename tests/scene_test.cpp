// Scene format v1: loading, the room, grids, sources, and one test per validation error
// (each asserting the line and key path a lighting designer is sent to).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "scene/grid_builder.hpp"
#include "scene/pts_reader.hpp"
#include "scene/scene_loader.hpp"
#include "scene_errors.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

const fs::path kSourceDir = PENUMBRA_SOURCE_DIR;
const fs::path kOffice = kSourceDir / "data" / "office.yaml";
const fs::path kCie171 = kSourceDir / "tests" / "validation" / "cie171";  // CIE 171:2006 cases

// The SceneError that parsing `yaml` throws; fails the test when it parses.
SceneError errorOf(const std::string& yaml, const fs::path& file = "test.yaml") {
  return testing::sceneErrorOf(yaml, file);
}

// Asserts line, key, and that the message contains `words`.
void expectError(const std::string& yaml, int line, const std::string& key,
                 const std::string& words) {
  const SceneError e = errorOf(yaml);
  EXPECT_EQ(e.line(), line) << e.what();
  EXPECT_EQ(e.key(), key) << e.what();
  EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  EXPECT_EQ(e.file(), fs::path("test.yaml"));
}

const Solid& solidNamed(const Scene& scene, const std::string& name) {
  for (const Solid& s : scene.solids) {
    if (s.name == name) return s;
  }
  throw std::runtime_error("no solid " + name);
}

// A scratch directory for files the tests write, removed at the end.
class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() /
            ("penumbra_scene_test_" +
             std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  fs::path write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name) << text;
    return path_ / name;
  }

 private:
  fs::path path_;
};

// ---------------------------------------------------------------- the example office

TEST(OfficeExample, LoadsWithExpectedCounts) {
  const Scene scene = loadScene(kOffice);
  // floor, ceiling, x0, x1, y1 whole, y0 in 4 pieces around the window; 2 desks + cabinet.
  EXPECT_EQ(scene.solids.size(), 2u + 3u + 4u + 3u);
  EXPECT_EQ(scene.sources.size(), 5u);
  EXPECT_EQ(scene.grids.size(), 3u);
  EXPECT_EQ(scene.materials.size(), 5u);
  ASSERT_TRUE(scene.room.has_value());
  EXPECT_EQ(scene.room->openings.size(), 1u);
  EXPECT_EQ(scene.grids[0].kind, GridKind::WorkPlane);
  EXPECT_EQ(scene.grids[1].kind, GridKind::Rect);
  EXPECT_EQ(scene.grids[2].kind, GridKind::Points);
  EXPECT_EQ(scene.grids[1].size(), 14u * 6u);
  EXPECT_EQ(scene.grids[2].size(), 5u);
  EXPECT_EQ(scene.materials[solidNamed(scene, "desk-1").material].name, "oak");
}

TEST(OfficeExample, FluxBecomesLuminance) {
  const Scene scene = loadScene(kOffice);
  const Source& panel = scene.sources[1];
  EXPECT_EQ(panel.name, "panel-1");
  EXPECT_NEAR(panel.emittingArea(), 0.36, 1e-12);
  EXPECT_NEAR(panel.luminance, 3400.0 / (std::numbers::pi * 0.36), 1e-9);
  EXPECT_TRUE(panel.faces[0].normal().isApprox(-Vec3::UnitZ(), 1e-12));
}

TEST(OfficeExample, SkyFillsTheWindowOnTheOuterFace) {
  const Scene scene = loadScene(kOffice);
  const Source& sky = scene.sources[0];
  ASSERT_EQ(sky.faces.size(), 1u);
  EXPECT_DOUBLE_EQ(sky.luminance, 4000.0);
  EXPECT_NEAR(sky.emittingArea(), 3.0, 1e-12);
  EXPECT_TRUE(sky.faces[0].normal().isApprox(Vec3::UnitY(), 1e-12));  // into the room
  for (const Vec3& v : sky.faces[0].vertices()) EXPECT_DOUBLE_EQ(v.y(), -0.2);
}

// ---------------------------------------------------------------- the room

const char* kRoomWithOpenings = R"(penumbra: 1
room:
  size: [6.0, 4.0, 3.0]
  wall_thickness: 0.25
  openings:
    - {name: w1, wall: y0, x: 0.5, z: 0.9, width: 1.5, height: 1.5}
    - {name: w2, wall: y0, x: 3.0, z: 1.2, width: 2.0, height: 1.0}
    - {name: door, wall: x1, x: 0.0, z: 0.0, width: 1.0, height: 2.1}
    - {name: high, wall: x1, x: 2.0, z: 2.0, width: 1.0, height: 1.0}
    - {name: w3, wall: y1, x: 1.0, z: 1.0, width: 1.0, height: 1.0}
    - {name: w4, wall: y1, x: 1.0, z: 2.0, width: 1.0, height: 0.5}
)";

TEST(Room, SlabVolumesSumToTheClosedForm) {
  const Scene scene = parseScene(kRoomWithOpenings, "test.yaml");
  const double x = 6.0, y = 4.0, z = 3.0, t = 0.25;
  double openings = 0.0;
  for (const double area : {1.5 * 1.5, 2.0 * 1.0, 1.0 * 2.1, 1.0 * 1.0, 1.0 * 1.0, 1.0 * 0.5}) {
    openings += area * t;
  }
  const double slabs = 2.0 * (x + 2 * t) * (y + 2 * t) * t;  // floor and ceiling
  const double walls = t * z * (2.0 * (x + 2 * t) + 2.0 * y);
  double sum = 0.0;
  for (const Solid& s : scene.solids) sum += s.shape.volume();
  EXPECT_NEAR(sum, slabs + walls - openings, 1e-9);
}

TEST(Room, SlabsDoNotOverlap) {
  const Scene scene = parseScene(kRoomWithOpenings, "test.yaml");
  // Every slab is a box: two overlap when their extents overlap by more than a hair on all axes.
  for (std::size_t i = 0; i < scene.solids.size(); ++i) {
    for (std::size_t j = i + 1; j < scene.solids.size(); ++j) {
      const auto bounds = [](const Solid& s) {
        Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
        for (const Vec3& v : s.shape.vertices()) {
          lo = lo.cwiseMin(v);
          hi = hi.cwiseMax(v);
        }
        return std::pair{lo, hi};
      };
      const auto [lo1, hi1] = bounds(scene.solids[i]);
      const auto [lo2, hi2] = bounds(scene.solids[j]);
      const Vec3 overlap = hi1.cwiseMin(hi2) - lo1.cwiseMax(lo2);
      EXPECT_FALSE((overlap.array() > 1e-9).all())
          << scene.solids[i].name << " overlaps " << scene.solids[j].name;
    }
  }
}

TEST(Room, SlabNamesAndMaterials) {
  const Scene scene = parseScene(R"(penumbra: 1
materials: {a: 0.1, b: 0.2, c: 0.3}
room:
  size: [4, 3, 2.5]
  materials: {floor: a, ceiling: b, walls: c}
  openings: [{name: w, wall: y0, x: 1, z: 1, width: 1, height: 1}]
)",
                                 "test.yaml");
  EXPECT_EQ(solidNamed(scene, "room.floor").material, 0);
  EXPECT_EQ(solidNamed(scene, "room.ceiling").material, 1);
  EXPECT_EQ(solidNamed(scene, "room.wall-x0").material, 2);
  EXPECT_EQ(solidNamed(scene, "room.wall-y1").material, 2);
  for (int i = 1; i <= 4; ++i)
    EXPECT_EQ(solidNamed(scene, "room.wall-y0." + std::to_string(i)).material, 2);
  EXPECT_DOUBLE_EQ(scene.room->wallThickness, 0.2);  // the default
  // Floor [-t, X+t] × [-t, Y+t] × [-t, 0].
  EXPECT_NEAR(solidNamed(scene, "room.floor").shape.volume(), 4.4 * 3.4 * 0.2, 1e-12);
}

TEST(Room, OpeningPolygonsFaceIntoTheRoom) {
  const Scene scene = parseScene(R"(penumbra: 1
room:
  size: [6, 4, 3]
  wall_thickness: 0.3
  openings:
    - {name: a, wall: x0, x: 1, z: 1, width: 1, height: 1}
    - {name: b, wall: x1, x: 1, z: 1, width: 1, height: 1}
    - {name: c, wall: y0, x: 1, z: 1, width: 1, height: 1}
    - {name: d, wall: y1, x: 1, z: 1, width: 1, height: 1}
)",
                                 "test.yaml");
  const Vec3 inward[] = {Vec3::UnitX(), -Vec3::UnitX(), Vec3::UnitY(), -Vec3::UnitY()};
  const double innerCoordinate[] = {0.0, 6.0, 0.0, 4.0};
  const double outerCoordinate[] = {-0.3, 6.3, -0.3, 4.3};
  ASSERT_EQ(scene.room->openings.size(), 4u);
  for (int i = 0; i < 4; ++i) {
    const Opening& o = scene.room->openings[i];
    const int across = i < 2 ? 0 : 1;
    EXPECT_TRUE(o.inner.normal().isApprox(inward[i], 1e-12)) << o.name;
    EXPECT_TRUE(o.outer.normal().isApprox(inward[i], 1e-12)) << o.name;
    EXPECT_NEAR(o.inner.area(), 1.0, 1e-12);
    for (const Vec3& v : o.inner.vertices()) EXPECT_NEAR(v[across], innerCoordinate[i], 1e-12);
    for (const Vec3& v : o.outer.vertices()) EXPECT_NEAR(v[across], outerCoordinate[i], 1e-12);
    // Position along the wall: x for y-walls, y for x-walls, from 1 to 2; z from 1 to 2.
    const int along = i < 2 ? 1 : 0;
    for (const Vec3& v : o.inner.vertices()) {
      EXPECT_TRUE(std::abs(v[along] - 1.0) < 1e-12 || std::abs(v[along] - 2.0) < 1e-12);
      EXPECT_TRUE(std::abs(v.z() - 1.0) < 1e-12 || std::abs(v.z() - 2.0) < 1e-12);
    }
  }
  EXPECT_EQ(scene.room->openings[0].wall, "x0");
}

TEST(Room, InnerPlaneOpeningSource) {
  const Scene scene = parseScene(R"(penumbra: 1
room:
  size: [4, 4, 3]
  openings: [{name: w, wall: y1, x: 1, z: 1, width: 2, height: 1}]
sources:
  - {name: sky, opening: w, plane: inner, luminance: 100}
)",
                                 "test.yaml");
  const ConvexPolygon& face = scene.sources[0].faces[0];
  EXPECT_TRUE(face.normal().isApprox(-Vec3::UnitY(), 1e-12));
  for (const Vec3& v : face.vertices()) EXPECT_DOUBLE_EQ(v.y(), 4.0);
}

// ---------------------------------------------------------------- grids

TEST(Grids, WorkPlaneFollowsEn12464) {
  const Scene scene = loadScene(kOffice);
  const CalculationGrid& g = scene.grids[0];
  const double sideX = 6.0 - 2 * 0.5, sideY = 4.0 - 2 * 0.5;
  const double p = 0.2 * std::pow(5.0, std::log10(std::max(sideX, sideY)));
  EXPECT_NEAR(p, 0.6160, 1e-4);
  const int nx = static_cast<int>(std::ceil(sideX / p));
  const int ny = static_cast<int>(std::ceil(sideY / p));
  EXPECT_EQ(nx, 9);
  EXPECT_EQ(ny, 5);
  EXPECT_EQ(g.columns, nx);
  EXPECT_EQ(g.rows, ny);
  ASSERT_EQ(g.size(), static_cast<std::size_t>(nx * ny));
  EXPECT_DOUBLE_EQ(g.spacing, std::max(sideX / nx, sideY / ny));
  EXPECT_LE(g.spacing, p);
  // Cell centres, row-major with rows along y.
  EXPECT_TRUE(g.position(0).isApprox(Vec3(0.5 + sideX / nx / 2, 0.5 + sideY / ny / 2, 0.8)));
  EXPECT_TRUE(g.position(1).isApprox(Vec3(0.5 + 1.5 * sideX / nx, 0.5 + sideY / ny / 2, 0.8)));
  EXPECT_TRUE(g.position(nx).isApprox(Vec3(0.5 + sideX / nx / 2, 0.5 + 1.5 * sideY / ny, 0.8)));
  for (std::size_t i = 0; i < g.size(); ++i) EXPECT_EQ(g.normal(i), Vec3::UnitZ());
}

TEST(Grids, WorkPlaneDefaultsAndExplicitSpacing) {
  const Scene scene = parseScene(R"(penumbra: 1
room: {size: [10, 8, 3]}
grids:
  - {name: a}
  - {name: b, spacing: 0.5, margin: 0, height: 0}
)",
                                 "test.yaml");
  const CalculationGrid& a = scene.grids[0];
  const double p = 0.2 * std::pow(5.0, std::log10(9.0));  // 9 × 7 m area
  EXPECT_EQ(a.columns, static_cast<int>(std::ceil(9.0 / p)));
  EXPECT_EQ(a.rows, static_cast<int>(std::ceil(7.0 / p)));
  EXPECT_DOUBLE_EQ(a.position(0).z(), 0.8);
  const CalculationGrid& b = scene.grids[1];
  EXPECT_EQ(b.columns, 20);
  EXPECT_EQ(b.rows, 16);
  EXPECT_DOUBLE_EQ(b.spacing, 0.5);
  EXPECT_TRUE(b.position(0).isApprox(Vec3(0.25, 0.25, 0.0)));
}

TEST(Grids, En12464SpacingClosedForm) {
  EXPECT_NEAR(scenefile::en12464Spacing(1.0), 0.2, 1e-12);
  EXPECT_NEAR(scenefile::en12464Spacing(10.0), 1.0, 1e-12);
  EXPECT_NEAR(scenefile::en12464Spacing(100.0), 5.0, 1e-12);
  EXPECT_NEAR(scenefile::en12464Spacing(1000.0), 10.0, 1e-12);  // capped
  EXPECT_EQ(scenefile::cellCount(1.4, 0.1), 14);
  EXPECT_EQ(scenefile::cellCount(0.3, 0.1), 3);
  EXPECT_EQ(scenefile::cellCount(0.05, 0.1), 1);
}

TEST(Grids, RectNormalIsUCrossV) {
  const Scene scene = parseScene(R"(penumbra: 1
grids:
  - {name: wall, rect: {origin: [0, 0, 0], u: [0, 2, 0], v: [0, 0, 1]}, spacing: 0.25}
)",
                                 "test.yaml");
  const CalculationGrid& g = scene.grids[0];
  EXPECT_EQ(g.columns, 8);
  EXPECT_EQ(g.rows, 4);
  EXPECT_DOUBLE_EQ(g.spacing, 0.25);
  EXPECT_TRUE(g.normal(0).isApprox(Vec3::UnitX()));
  EXPECT_TRUE(g.position(0).isApprox(Vec3(0, 0.125, 0.125)));
}

TEST(Grids, InlinePointsAreNormalised) {
  const Scene scene = parseScene(R"(penumbra: 1
grids:
  - {name: s, points: [[1, 2, 3, 0, 0, 2], [4, 5, 6, 3, 4, 0]]}
)",
                                 "test.yaml");
  const CalculationGrid& g = scene.grids[0];
  EXPECT_EQ(g.kind, GridKind::Points);
  ASSERT_EQ(g.size(), 2u);
  EXPECT_EQ(g.position(1), Vec3(4, 5, 6));
  EXPECT_TRUE(g.normal(0).isApprox(Vec3::UnitZ()));
  EXPECT_TRUE(g.normal(1).isApprox(Vec3(0.6, 0.8, 0)));
  EXPECT_EQ(g.spacing, 0.0);
}

TEST(Pts, ParsesRadianceSensorFiles) {
  const scenefile::SensorPoints pts = scenefile::parsePts(
      "# comment\n1 2 3 0 0 1\n\n  4\t5 6   0 -2 0  \r\n", "s.pts", "grids[0].points");
  ASSERT_EQ(pts.positions.size(), 2u);
  EXPECT_EQ(pts.positions[1], Vec3(4, 5, 6));
  EXPECT_TRUE(pts.normals[1].isApprox(-Vec3::UnitY()));
}

TEST(Pts, ErrorsNameThePtsFileAndLine) {
  try {
    scenefile::parsePts("1 2 3 0 0 1\n1 2 3 0 0\n", "s.pts", "grids[0].points");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), fs::path("s.pts"));
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.key(), "grids[0].points");
  }
  try {
    scenefile::parsePts("1 2 3 0 0 1\n\n1 2 x 0 0 1\n", "s.pts", "k");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 3);
  }
  try {
    scenefile::parsePts("1 2 3 0 0 0\n", "s.pts", "k");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(std::string(e.what()).find("zero"), std::string::npos);
  }
}

// From the pts fuzz target (tests/fuzz/regressions/pts): a normal of 7.7e157 squared overflows,
// and normalized() would give a NaN normal, which the kernel turns into NaN illuminance; a normal
// of 3e-300 squared underflows, and would be rejected as the zero vector.
TEST(Pts, HugeAndTinyNormalsBecomeUnitVectors) {
  const scenefile::SensorPoints pts =
      scenefile::parsePts("0 0 0 0 1e200 1e200\n0 0 0 -3e-300 0 0\n", "s.pts", "k");
  ASSERT_EQ(pts.normals.size(), 2u);
  const double half = std::sqrt(0.5);
  EXPECT_NEAR((pts.normals[0] - Vec3(0, half, half)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((pts.normals[1] - Vec3(-1, 0, 0)).norm(), 0.0, 1e-15);
}

TEST(Pts, HugeNormalsInTheSceneBecomeUnitVectors) {
  const Scene scene = parseScene(R"(penumbra: 1
grids:
  - name: s
    points: [[0, 0, 0, 1e300, 0, 1e300]]
)",
                                 "test.yaml");
  const double half = std::sqrt(0.5);
  EXPECT_NEAR((scene.grids.at(0).normal(0) - Vec3(half, 0, half)).norm(), 0.0, 1e-15);
}

TEST(Pts, OfficeSensorsResolveRelativeToTheScene) {
  const Scene scene = loadScene(kOffice);
  const CalculationGrid& g = scene.grids[2];
  EXPECT_EQ(g.position(0), Vec3(1.8, 1.4, 0.75));
  EXPECT_EQ(g.normal(2), -Vec3::UnitY());
}

// ---------------------------------------------------------------- sources and solids

TEST(Sources, RectWidthRunsAlongX) {
  const Scene scene = parseScene(R"(penumbra: 1
sources:
  - {name: down, rect: {center: [1, 2, 3], size: [0.4, 0.2], normal: [0, 0, -1]}, luminance: 1}
  - {name: side, rect: {center: [0, 0, 0], size: [0.4, 0.2], normal: [1, 0, 0]}, luminance: 1}
)",
                                 "test.yaml");
  const ConvexPolygon& down = scene.sources[0].faces[0];
  EXPECT_TRUE(down.normal().isApprox(-Vec3::UnitZ()));
  EXPECT_TRUE(down.centroid().isApprox(Vec3(1, 2, 3)));
  EXPECT_NEAR((down.vertices()[1] - down.vertices()[0]).norm(), 0.4, 1e-12);
  EXPECT_TRUE((down.vertices()[1] - down.vertices()[0]).normalized().isApprox(Vec3::UnitX()));
  const ConvexPolygon& side = scene.sources[1].faces[0];
  EXPECT_TRUE(side.normal().isApprox(Vec3::UnitX()));
  EXPECT_TRUE((side.vertices()[1] - side.vertices()[0]).normalized().isApprox(Vec3::UnitY()));
  EXPECT_NEAR(side.area(), 0.08, 1e-12);
}

TEST(Sources, PolygonIsStoredCounterClockwiseAboutItsNormal) {
  const Scene scene = parseScene(R"(penumbra: 1
sources:
  - {name: given, polygon: [[0, 0, 2], [1, 0, 2], [1, 1, 2], [0, 1, 2]], normal: [0, 0, -1], luminance: 10}
  - {name: implied, polygon: [[0, 0, 2], [1, 0, 2], [1, 1, 2], [0, 1, 2]], luminance: 10, color: [1, 0.9, 0.8]}
)",
                                 "test.yaml");
  EXPECT_TRUE(scene.sources[0].faces[0].normal().isApprox(-Vec3::UnitZ()));
  EXPECT_TRUE(scene.sources[1].faces[0].normal().isApprox(Vec3::UnitZ()));
  EXPECT_EQ(scene.sources[0].color, Vec3::Ones());
  EXPECT_EQ(scene.sources[1].color, Vec3(1, 0.9, 0.8));
  EXPECT_EQ(scene.sources[0].shape, SourceShape::Polygon);
}

TEST(Sources, PolyhedronSourceEmitsFromEveryFaceOutwards) {
  const Scene scene = parseScene(R"(penumbra: 1
sources:
  - {name: cube, box: {min: [0, 0, 0], max: [1, 2, 3]}, flux: 1000}
)",
                                 "test.yaml");
  const Source& s = scene.sources[0];
  EXPECT_EQ(s.shape, SourceShape::Polyhedron);
  ASSERT_EQ(s.faces.size(), 6u);
  const double area = 2 * (1 * 2 + 2 * 3 + 1 * 3);
  EXPECT_NEAR(s.emittingArea(), area, 1e-12);
  EXPECT_NEAR(s.luminance, 1000.0 / (std::numbers::pi * area), 1e-12);
  const Vec3 centre(0.5, 1.0, 1.5);
  for (const ConvexPolygon& f : s.faces) EXPECT_GT(f.normal().dot(f.centroid() - centre), 0.0);
}

TEST(Solids, PrismHullAndBox) {
  const Scene scene = parseScene(R"(penumbra: 1
solids:
  - {name: column, prism: {base: [[4, 3, 0], [4.3, 3, 0], [4.3, 3.3, 0], [4, 3.3, 0]], height: 3.0}}
  - {name: column-cw, prism: {base: [[4, 3.3, 0], [4.3, 3.3, 0], [4.3, 3, 0], [4, 3, 0]], height: 3.0}}
  - {name: rock, hull: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.3, 0.3, 0.3]]}
  - {name: b, box: {min: [0, 0, 0], max: [1, 1, 1]}}
)",
                                 "test.yaml");
  ASSERT_EQ(scene.solids.size(), 4u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(scene.solids[i].shape.volume(), 0.3 * 0.3 * 3.0, 1e-12);
    EXPECT_NEAR(scene.solids[i].shape.centroid().z(), 1.5, 1e-12);  // upwards either way round
  }
  EXPECT_NEAR(scene.solids[2].shape.volume(), 1.0 / 6.0, 1e-12);
  EXPECT_EQ(scene.solids[3].material, -1);
}

TEST(SceneSize, IsTheDiagonalOfAllGeometry) {
  const Scene scene = parseScene(R"(penumbra: 1
solids: [{name: b, box: {min: [0, 0, 0], max: [1, 2, 2]}}]
)",
                                 "test.yaml");
  EXPECT_NEAR(scene.size(), 3.0, 1e-12);
}

// ---------------------------------------------------------------- CIE 171 validation scenes

TEST(Cie171, ValidationScenesLoad) {
  for (const char* name : {"tc5.3", "tc5.6", "tc5.7", "tc5.11"}) {
    SCOPED_TRACE(name);
    const Scene scene = loadScene(kCie171 / (std::string(name) + ".yaml"));
    EXPECT_EQ(scene.sources.size(), 1u);
    EXPECT_FALSE(scene.grids.empty());
    for (const Source& s : scene.sources) EXPECT_GT(s.emittingArea(), 0.0);
  }
  const Scene tc511 = loadScene(kCie171 / "tc5.11.yaml");
  // Typed clockwise about +y with normal +y: stored reversed, emitting into the room.
  EXPECT_TRUE(tc511.sources[0].faces[0].normal().isApprox(Vec3::UnitY()));
  EXPECT_EQ(tc511.room->openings.size(), 1u);
  EXPECT_EQ(tc511.solids.size(), 2u + 3u + 4u);
  const Scene tc56 = loadScene(kCie171 / "tc5.6.yaml");
  EXPECT_FALSE(tc56.room.has_value());
  EXPECT_EQ(tc56.grids[1].size(), 8u);
  const Scene tc57 = loadScene(kCie171 / "tc5.7.yaml");
  EXPECT_EQ(tc57.solids.size(), 6u + 1u);
}

// ---------------------------------------------------------------- validation errors

TEST(Errors, NonConvexPolygon) {
  expectError(R"(penumbra: 1
sources:
  - name: dart
    polygon: [[0, 0, 2], [2, 0, 2], [2, 2, 2], [1.5, 0.5, 2]]
    luminance: 100
)",
              4, "sources[0].polygon", "not convex");
}

TEST(Errors, NonPlanarPolygon) {
  expectError(R"(penumbra: 1
sources:
  - {name: warped, polygon: [[0, 0, 2], [1, 0, 2], [1, 1, 2.1], [0, 1, 2]], luminance: 100}
)",
              3, "sources[0].polygon", "not planar");
}

TEST(Errors, NonConvexPrismBase) {
  expectError(R"(penumbra: 1
solids:
  - name: l-shape
    prism:
      base: [[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0]]
      height: 1
)",
              5, "solids[0].prism.base", "not convex");
}

TEST(Errors, ZeroAreaPolygon) {
  expectError(R"(penumbra: 1
sources:
  - {name: line, polygon: [[0, 0, 2], [1, 0, 2], [2, 0, 2]], luminance: 100}
)",
              3, "sources[0].polygon", "zero area");
}

TEST(Errors, ZeroVolumeSolids) {
  expectError(R"(penumbra: 1
solids:
  - {name: flat, hull: [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]]}
)",
              3, "solids[0].hull", "no volume");
  expectError(R"(penumbra: 1
solids:
  - {name: flat, box: {min: [0, 0, 0], max: [1, 1, 0]}}
)",
              3, "solids[0].box", "no volume");
}

// A solid thinner than the kernels resolve where it lies is refused (Tolerance::minimumThickness:
// 100 kernel length tolerances, 1e-4 of its farthest coordinate from the centre of the scene's
// geometry; the float kernels err at its shadow boundaries below that). The geometry below spans
// [0, 10] × [0, 10] × [-0.1, 2] m, centre (5, 5, 0.95): the pane reaches 3 m from it, where the
// limit is 0.3 mm. The thickness is measured across faces, whatever the solid's orientation.
TEST(Errors, SolidsThinnerThanTheKernelsResolve) {
  const std::string head = R"(penumbra: 1
sources:
  - {name: panel, rect: {center: [5, 5, 2], size: [1, 1], normal: [0, 0, -1]}, luminance: 1000}
solids:
  - {name: floor, box: {min: [0, 0, -0.1], max: [10, 10, 0]}}
)";
  const SceneError e =
      errorOf(head + "  - {name: pane, box: {min: [2, 2, 0.5], max: [3, 2.0001, 1.5]}}\n");
  EXPECT_EQ(e.line(), 6) << e.what();
  EXPECT_EQ(e.key(), "solids[1].box") << e.what();
  EXPECT_NE(std::string(e.what()).find("solid 'pane' is 0.1 mm thick"), std::string::npos)
      << e.what();
  EXPECT_NE(std::string(e.what()).find("reaches 3 m from the centre"), std::string::npos)
      << e.what();
  EXPECT_NE(std::string(e.what()).find("shade solids from 0.3 mm"), std::string::npos) << e.what();
  // A tilted slab, 0.2 mm thick across its faces (its axis-aligned extents are far larger).
  const SceneError tilted =
      errorOf(head +
              "  - {name: louvre, hull: [[2, 2, 1], [3, 2, 1], [2, 2.5, 1.5], [3, 2.5, 1.5], "
              "[2, 2.00014142, 0.99985858], [3, 2.00014142, 0.99985858], "
              "[2, 2.50014142, 1.49985858], [3, 2.50014142, 1.49985858]]}\n");
  EXPECT_EQ(tilted.key(), "solids[1].hull") << tilted.what();
  EXPECT_NE(std::string(tilted.what()).find("'louvre' is 0.2 mm thick"), std::string::npos)
      << tilted.what();
  // Just above the limit loads, and keeps its thickness; so does a 10 mm pane, which a limit of
  // 1/1000 of the scene's size (14.3 mm here) refused.
  for (const double t : {0.00035, 0.01}) {
    const Scene scene = parseScene(
        head + fmt::format("  - {{name: pane, box: {{min: [2, 2, 0.5], max: [3, {}, 1.5]}}}}\n",
                           2.0 + t),
        "test.yaml");
    EXPECT_NEAR(solidNamed(scene, "pane").shape.thickness(), t, 1e-12);
  }
}

TEST(Errors, NormalNotPerpendicular) {
  expectError(R"(penumbra: 1
sources:
  - name: tilted
    polygon: [[0, 0, 2], [1, 0, 2], [1, 1, 2], [0, 1, 2]]
    normal: [0, 1, 0]
    luminance: 100
)",
              5, "sources[0].normal", "not perpendicular");
}

TEST(Errors, UnknownKeyAtTheTop) {
  expectError(R"(penumbra: 1
lights: []
)",
              2, "lights",
              "a scene accepts: penumbra, parameters, materials, room, solids, sources, grids");
}

TEST(Errors, UnknownKeyInASource) {
  expectError(R"(penumbra: 1
sources:
  - {name: a, rect: {center: [0, 0, 2], size: [1, 1], normal: [0, 0, -1]}, luminance: 1}
  - name: b
    rect: {center: [0, 0, 2], size: [1, 1], normal: [0, 0, -1]}
    lumens: 3400
)",
              6, "sources[1].lumens", "name, rect, luminance, flux, color");
}

TEST(Errors, UnknownKeyNested) {
  expectError(R"(penumbra: 1
solids:
  - name: desk
    box: {min: [0, 0, 0], centre: [1, 1, 1]}
)",
              4, "solids[0].box.centre", "a box accepts: min, max");
  expectError(R"(penumbra: 1
room:
  size: [4, 4, 3]
  openings:
    - {name: w, wall: y0, x: 1, sill: 1, width: 1, height: 1}
)",
              5, "room.openings[0].sill", "name, wall, x, z, width, height");
  expectError(R"(penumbra: 1
room:
  size: [4, 4, 3]
  wall_thicknes: 0.2
)",
              4, "room.wall_thicknes", "size, wall_thickness, materials, openings");
  expectError(R"(penumbra: 1
room: {size: [4, 4, 3]}
grids:
  - {name: g, height: 0.8, spacing: auto, margins: 0.5}
)",
              4, "grids[0].margins", "name, height, spacing, margin");
}

TEST(Errors, UnknownMaterial) {
  expectError(R"(penumbra: 1
materials: {paint: 0.8, oak: [0.35, 0.27, 0.18]}
solids:
  - {name: desk, box: {min: [0, 0, 0], max: [1, 1, 1]}, material: maple}
)",
              4, "solids[0].material", "materials defined: paint, oak");
  expectError(R"(penumbra: 1
materials: {paint: 0.8}
room:
  size: [4, 4, 3]
  materials:
    floor: paint
    walls: plaster
)",
              7, "room.materials.walls", "unknown material 'plaster'");
}

TEST(Errors, NegativeLuminance) {
  expectError(R"(penumbra: 1
sources:
  - name: panel
    rect: {center: [0, 0, 2], size: [1, 1], normal: [0, 0, -1]}
    luminance: -100
)",
              5, "sources[0].luminance", "must not be negative");
}

TEST(Errors, NegativeFlux) {
  expectError(R"(penumbra: 1
sources:
  - {name: panel, rect: {center: [0, 0, 2], size: [1, 1], normal: [0, 0, -1]}, flux: -3400}
)",
              3, "sources[0].flux", "must not be negative");
}

TEST(Errors, LuminanceAndFluxBothOrNeither) {
  expectError(R"(penumbra: 1
sources:
  - {name: p, rect: {center: [0, 0, 2], size: [1, 1], normal: [0, 0, -1]}, flux: 1, luminance: 1}
)",
              3, "sources[0].flux", "not both");
  expectError(R"(penumbra: 1
sources:
  - {name: p, rect: {center: [0, 0, 2], size: [1, 1], normal: [0, 0, -1]}}
)",
              3, "sources[0]", "'luminance' (cd/m²) or 'flux' (lm)");
}

TEST(Errors, ReflectanceOutsideZeroOne) {
  expectError(R"(penumbra: 1
materials:
  paint: 0.8
  glossy: 80
)",
              4, "materials.glossy", "[0, 1]");
  expectError(R"(penumbra: 1
materials: {oak: [0.35, 1.27, 0.18]}
)",
              2, "materials.oak", "[0, 1]");
}

TEST(Errors, OpeningOutsideItsWall) {
  expectError(R"(penumbra: 1
room:
  size: [6, 4, 3]
  openings:
    - {name: ok, wall: y0, x: 1, z: 1, width: 1, height: 1}
    - {name: window-2, wall: y0, x: 5.5, z: 1, width: 1, height: 1}
)",
              6, "room.openings[1]", "opening 'window-2' does not fit in wall y0");
  expectError(R"(penumbra: 1
room:
  size: [6, 4, 3]
  openings:
    - {name: tall, wall: x1, x: 1, z: 2, width: 1, height: 1.5}
)",
              5, "room.openings[0]", "opening 'tall' does not fit in wall x1");
}

TEST(Errors, OverlappingOpenings) {
  expectError(R"(penumbra: 1
room:
  size: [6, 4, 3]
  openings:
    - {name: a, wall: y1, x: 1, z: 1, width: 2, height: 1}
    - {name: b, wall: y1, x: 2.5, z: 1.5, width: 1, height: 1}
)",
              6, "room.openings[1]", "opening 'b' overlaps opening 'a'");
}

TEST(Errors, OpeningSourceWithoutSuchOpening) {
  expectError(R"(penumbra: 1
room:
  size: [6, 4, 3]
  openings: [{name: w, wall: y0, x: 1, z: 1, width: 1, height: 1}]
sources:
  - {name: sky, opening: window, luminance: 1000}
)",
              6, "sources[0].opening", "unknown opening 'window'; the room's openings: w");
}

TEST(Errors, GridWithNoPoints) {
  expectError(R"(penumbra: 1
grids:
  - {name: empty, points: []}
)",
              3, "grids[0].points", "no points");
  expectError(R"(penumbra: 1
room: {size: [2, 2, 3]}
grids:
  - {name: wp, margin: 1.0}
)",
              4, "grids[0].margin", "no points");
  expectError(R"(penumbra: 1
grids:
  - {name: flat, rect: {origin: [0, 0, 0], u: [1, 0, 0], v: [0, 0, 0]}}
)",
              3, "grids[0].rect.v", "no points");
  TempDir dir;
  dir.write("empty.pts", "# nothing here\n\n");
  const fs::path scene =
      dir.write("s.yaml", "penumbra: 1\ngrids:\n  - {name: s, points: empty.pts}\n");
  try {
    loadScene(scene);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.key(), "grids[0].points");
    EXPECT_NE(std::string(e.what()).find("no points"), std::string::npos);
  }
}

TEST(Errors, WorkPlaneWithoutRoom) {
  expectError(R"(penumbra: 1
grids:
  - {name: wp, height: 0.8}
)",
              3, "grids[0]", "no 'room:'");
}

TEST(Errors, ZeroNormalInPoints) {
  expectError(R"(penumbra: 1
grids:
  - name: s
    points:
      - [0, 0, 0, 0, 0, 1]
      - [1, 0, 0, 0, 0, 0]
)",
              6, "grids[0].points[1]", "zero vector");
}

TEST(Errors, MissingSceneFile) {
  try {
    loadScene("/no/such/scene.yaml");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), fs::path("/no/such/scene.yaml"));
    EXPECT_EQ(e.line(), 0);
    EXPECT_EQ(e.key(), "");
  }
}

TEST(Errors, MissingPtsFile) {
  TempDir dir;
  const fs::path scene =
      dir.write("s.yaml", "penumbra: 1\ngrids:\n  - name: s\n    points: missing.pts\n");
  try {
    loadScene(scene);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), scene);
    EXPECT_EQ(e.line(), 4);
    EXPECT_EQ(e.key(), "grids[0].points");
    EXPECT_NE(std::string(e.what()).find("missing.pts"), std::string::npos);
  }
}

TEST(Errors, PtsFileErrorsPointIntoThePtsFile) {
  TempDir dir;
  const fs::path pts = dir.write("bad.pts", "0 0 0 0 0 1\n0 0 0 0 0\n");
  const fs::path scene = dir.write("s.yaml", "penumbra: 1\ngrids: [{name: s, points: bad.pts}]\n");
  try {
    loadScene(scene);
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(e.file(), pts);
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.key(), "grids[0].points");
  }
}

TEST(Errors, WrongVersion) {
  expectError("penumbra: 2\n", 1, "penumbra", "version 1");
  expectError("materials: {a: 0.5}\n", 1, "penumbra", "'penumbra: 1'");
  expectError("", 0, "", "empty");
}

TEST(Errors, DuplicateNames) {
  expectError(R"(penumbra: 1
sources:
  - {name: p, rect: {center: [0, 0, 2], size: [1, 1], normal: [0, 0, -1]}, flux: 1}
  - {name: q, rect: {center: [1, 0, 2], size: [1, 1], normal: [0, 0, -1]}, flux: 1}
  - {name: p, rect: {center: [2, 0, 2], size: [1, 1], normal: [0, 0, -1]}, flux: 1}
)",
              5, "sources[2]", "already used in sources by sources[0] (line 3)");
  expectError(R"(penumbra: 1
solids:
  - {name: room.floor, box: {min: [0, 0, 0], max: [1, 1, 1]}}
)",
              3, "solids[0].name", "kept for the room");
  expectError(R"(penumbra: 1
materials:
  paint: 0.8
  paint: 0.7
)",
              4, "materials.paint", "appears twice");
}

// A flow map or list without its '}' or ']' is named on the line that opened it, not on the next
// line, where the parser notices.
TEST(Errors, AMissingClosingBracketIsNamedOnItsLine) {
  expectError(R"(penumbra: 1
sources:
  - {name: p, polygon: [[0, 0, 2], [1, 0, 2], [1, 1, 2]], luminance: 1
grids: []
)",
              3, "", "not valid YAML: the '{' opened on this line is not closed with '}'");
  expectError(R"(penumbra: 1
# a comment with { and a "quoted [" do not count
room: {size: [3, 3, 3]}
solids:
  - {name: desk, box: {min: [0, 0, 0], max: [1, 1, 0.7]}
  - {name: shelf, box: {min: ["1", 0, 0], max: [2, 1, 2]}}
grids: []
)",
              5, "", "not valid YAML: the '{' opened on this line is not closed with '}'");
  expectError(R"(penumbra: 1
room: {size: [3, 3, 3}
grids: []
)",
              2, "", "not valid YAML");
}

TEST(Errors, WrongTypes) {
  expectError(R"(penumbra: 1
sources:
  - {name: p, rect: {center: [0, 0, 2], size: [1, 1], normal: [0, 0, -1]}, flux: 3400 lm}
)",
              3, "sources[0].flux", "expected a number, got '3400 lm'");
  expectError(R"(penumbra: 1
solids:
  - {name: b, box: {min: [0, 0], max: [1, 1, 1]}}
)",
              3, "solids[0].box.min", "3 numbers");
  expectError(R"(penumbra: 1
solids:
  - {name: b}
)",
              3, "solids[0]", "needs a shape: one of box, prism, hull");
}

TEST(Errors, AMisspeltShapeKeyIsNamed) {
  expectError(R"(penumbra: 1
solids:
  - name: desk
    bx: {min: [0, 0, 0], max: [1, 1, 1]}
)",
              4, "solids[0].bx", "unknown key 'bx'; a solid needs a shape: one of box, prism");
  expectError(R"(penumbra: 1
sources:
  - {name: panel, rct: {center: [1, 1, 2.8], size: [1, 1], normal: [0, 0, -1]}, luminance: 1}
)",
              3, "sources[0].rct", "unknown key 'rct'; a source needs a shape: one of");
}

TEST(Errors, ATabInTheIndentationIsNamed) {
  expectError("penumbra: 1\nsolids:\n  - name: desk\n\tbox: {min: [0, 0, 0], max: [1, 1, 1]}\n", 4,
              "", "indented with a tab, and YAML does not allow tabs in indentation");
  // A tab elsewhere in a valid file is fine.
  EXPECT_NO_THROW(parseScene("penumbra: 1\nmaterials: {paint:\t0.8}\n", "test.yaml"));
}

TEST(Errors, MessageNamesFileLineAndKey) {
  const SceneError e = errorOf(
      "penumbra: 1\nsources: [{name: p, polygon: [[0,0,0],[1,0,0],[0,1,0]], luminance: -1}]\n",
      "rooms/office.yaml");
  EXPECT_EQ(std::string(e.what()).rfind("rooms/office.yaml:2: sources[0].luminance: ", 0), 0u)
      << e.what();
}

}  // namespace
}  // namespace penumbra
