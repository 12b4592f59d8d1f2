// The files for ParaView: a grid's .vti/.vtp read back with VTK against its CSV, and
// surfaces.vtp against the engine and a closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include "engine/illuminance_engine.hpp"
#include "geometry/tolerance.hpp"
#include "illuminance/estimator.hpp"
#include "output/number_text.hpp"
#include "output/result_files.hpp"
#include "test_device.hpp"
#include "test_files.hpp"
#include "test_scenes.hpp"
#include "viz/grid_dataset.hpp"
#include "viz/surfaces_plot.hpp"
#include "viz_test_support.hpp"

namespace penumbra::viz {
namespace {

namespace fs = std::filesystem;
using penumbra::testing::hillGrid;
using penumbra::testing::lines;
using penumbra::testing::readText;
using penumbra::testing::TempDir;

struct CsvPoint {
  double position[3], normal[3], e;
};

// The CSV as a user's script reads it: split on commas, strtod.
std::vector<CsvPoint> readCsv(const fs::path& file) {
  std::vector<CsvPoint> rows;
  const auto all = lines(readText(file));
  for (std::size_t i = 1; i < all.size(); ++i) {
    std::vector<double> v;
    std::stringstream fields(all[i]);
    std::string field;
    for (int k = 0; k < 7 && std::getline(fields, field, ','); ++k) {
      v.push_back(std::strtod(field.c_str(), nullptr));
    }
    rows.push_back({{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6]});
  }
  return rows;
}

// A grid on the wall x = 5.9 facing the room (-x): u runs along -y, v up.
GridReport wallGrid() {
  GridReport grid;
  grid.name = "wall";
  grid.kind = GridKind::Rect;
  grid.columns = 7;
  grid.rows = 4;
  for (int r = 0; r < grid.rows; ++r) {
    for (int c = 0; c < grid.columns; ++c) {
      grid.points.push_back({Vec3(5.9, 3.5 - 0.3 * c, 0.5 + 0.3 * r), -Vec3::UnitX(), -1});
      grid.illuminance.push_back(100.0 / 7.0 * (c + 1) + std::sqrt(2.0) * r);
      grid.insideSolids.emplace_back(c == 2 && r == 1 ? "cabinet" : "");
    }
  }
  return grid;
}

vtkSmartPointer<vtkImageData> readVti(const fs::path& file) {
  auto reader = vtkSmartPointer<vtkXMLImageDataReader>::New();
  reader->SetFileName(file.string().c_str());
  reader->Update();
  return reader->GetOutput();
}

class GridDataset : public ::testing::TestWithParam<GridReport (*)()> {};

TEST_P(GridDataset, VtiReadBackEqualsTheCsvExactly) {
  TempDir dir("viz-data");
  RunReport run;
  run.grids.push_back(GetParam()());
  writeResults(run, dir.path());
  // The plots draw the results as written (`penumbra plot` and a sweep's case plots read them
  // back): E with the digits it holds.
  GridReport grid = run.grids[0];
  for (double& e : grid.illuminance) e = withDigits(e, illuminanceDigits(run));
  ASSERT_EQ(gridDatasetFileName(grid), grid.name + ".vti");
  writeGridDataset(grid, dir.path() / gridDatasetFileName(grid));

  const std::vector<CsvPoint> csv = readCsv(dir.path() / (grid.name + ".csv"));
  const vtkSmartPointer<vtkImageData> image = readVti(dir.path() / (grid.name + ".vti"));
  ASSERT_EQ(image->GetNumberOfPoints(), static_cast<vtkIdType>(csv.size()));
  EXPECT_EQ(image->GetDimensions()[0], grid.columns);
  EXPECT_EQ(image->GetDimensions()[1], grid.rows);
  vtkDataArray* e = image->GetPointData()->GetArray("E_lx");
  vtkDataArray* normals = image->GetPointData()->GetNormals();
  vtkDataArray* inside = image->GetPointData()->GetArray("inside_solid");
  ASSERT_NE(e, nullptr);
  ASSERT_NE(normals, nullptr);
  ASSERT_NE(inside, nullptr);
  EXPECT_EQ(e->GetDataType(), VTK_DOUBLE);
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i) {
    EXPECT_EQ(e->GetTuple1(i), csv[i].e) << "point " << i;
    double point[3];
    image->GetPoint(i, point);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(normals->GetComponent(i, k), csv[i].normal[k]) << "point " << i;
      // The lattice (origin, spacing, direction) puts every point where the CSV has it.
      EXPECT_NEAR(point[k], csv[i].position[k], 1e-12) << "point " << i;
    }
    EXPECT_EQ(inside->GetTuple1(i), grid.insideSolids[i].empty() ? 0.0 : 1.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Grids, GridDataset,
                         ::testing::Values(
                             +[] { return hillGrid(); }, +[] { return wallGrid(); }),
                         [](const auto& info) {
                           return std::string(info.index == 0 ? "horizontal" : "on_a_wall");
                         });

TEST(GridDataset, APointListIsPolyDataWithTheSameValues) {
  TempDir dir("viz-data");
  GridReport grid;
  grid.name = "sensors";
  grid.kind = GridKind::Points;
  grid.points = {{Vec3(1, 2, 0.8), Vec3::UnitZ(), -1}, {Vec3(0.1, 3, 1.2), Vec3::UnitY(), -1}};
  grid.illuminance = {1.0 / 3.0, 2.0 / 7.0};
  grid.insideSolids = {"", ""};
  ASSERT_EQ(gridDatasetFileName(grid), "sensors.vtp");
  writeGridDataset(grid, dir.path() / "sensors.vtp");
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName((dir.path() / "sensors.vtp").string().c_str());
  reader->Update();
  vtkPolyData* data = reader->GetOutput();
  ASSERT_EQ(data->GetNumberOfPoints(), 2);
  EXPECT_EQ(data->GetNumberOfVerts(), 2);
  for (vtkIdType i = 0; i < 2; ++i) {
    EXPECT_EQ(data->GetPointData()->GetArray("E_lx")->GetTuple1(i), grid.illuminance[i]);
    double p[3];
    data->GetPoint(i, p);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(p[k], grid.points[i].position[k]);
  }
}

// A 4 × 4 × 3 m room, a 1 m² ceiling panel of 1000 cd/m² over [1.5, 2.5]², a table beside the
// spot under it; grey floor (ρ = 0.2), no material on the table.
constexpr const char* kPanelRoom = R"(penumbra: 1
materials: {floor-grey: 0.2, paint: [0.8, 0.7, 0.6]}
room:
  size: [4.0, 4.0, 3.0]
  wall_thickness: 0.2
  materials: {floor: floor-grey, ceiling: paint, walls: paint}
solids:
  - {name: table, box: {min: [1.3, 1.3, 0.0], max: [1.7, 1.7, 0.75]}}
sources:
  - {name: panel, polygon: [[1.5, 1.5, 2.99], [2.5, 1.5, 2.99], [2.5, 2.5, 2.99], [1.5, 2.5, 2.99]], normal: [0.0, 0.0, -1.0], luminance: 1000.0}
)";

// E under a parallel rectangle [x0, x1] × [y0, y1] at height h above a point facing it: the
// catalogue's corner factor, added and subtracted over the four corners.
double closedForm(double x, double y, double h, double luminance) {
  const auto f = [&](double a, double b) {
    return penumbra::testing::parallelCornerFactor(a, b, h);
  };
  const double x0 = 1.5 - x, x1 = 2.5 - x, y0 = 1.5 - y, y1 = 2.5 - y;
  return std::numbers::pi * luminance * (f(x1, y1) - f(x0, y1) - f(x1, y0) + f(x0, y0));
}

// Every 7th point of a surfaces.vtp with the solid whose face it lies on (found here from the
// geometry, not from the file), and the file's E and L there.
struct SurfaceSamples {
  vtkIdType total = 0;  // points in the file
  std::vector<SamplePoint> points;
  std::vector<double> illuminance, luminance;  // lx, cd/m²
};

SurfaceSamples readSurfaceSamples(const fs::path& vtp, const Scene& scene) {
  SurfaceSamples samples;
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(vtp.string().c_str());
  reader->Update();
  vtkPolyData* surfaces = reader->GetOutput();
  vtkDataArray* e = surfaces->GetPointData()->GetArray("E_lx");
  vtkDataArray* l = surfaces->GetPointData()->GetArray("L_cd_m2");
  vtkDataArray* normals = surfaces->GetPointData()->GetNormals();
  if (!(e && l && normals)) {
    ADD_FAILURE() << vtp << " lacks E_lx, L_cd_m2 or normals";
    return samples;
  }
  samples.total = surfaces->GetNumberOfPoints();
  const double tolerance = 1e-6 * scene.size();
  for (vtkIdType i = 0; i < samples.total; i += 7) {
    SamplePoint p;
    surfaces->GetPoint(i, p.position.data());
    normals->GetTuple(i, p.normal.data());
    for (int s = 0; s < static_cast<int>(scene.solids.size()); ++s) {
      const int face = scene.solids[s].shape.faceContaining(p.position, p.normal, tolerance);
      if (face >= 0 && scene.solids[s].shape.faces()[face].plane.normal.dot(p.normal) > 0.999) {
        p.solid = s;
      }
    }
    if (p.solid < 0) ADD_FAILURE() << "point " << i << " lies on no face";
    samples.points.push_back(p);
    samples.illuminance.push_back(e->GetTuple1(i));
    samples.luminance.push_back(l->GetTuple1(i));
  }
  return samples;
}

// The panel room's surfaces sampled 0.25 m apart, drawn 800 px wide, on the CPU device.
PlotOptions panelRoomPlotOptions() {
  PlotOptions options;
  options.device = "cpu";
  options.surfaceSpacing = 0.25;
  options.width = 800;
  return options;
}

TEST(SurfacesFile, IlluminanceEqualsTheEngineAndTheClosedForm) {
  compute::Device* device = nullptr;
  try {
    device = &penumbra::testing::cpuDevice();
  } catch (const std::exception& e) {
    GTEST_SKIP() << "no OpenCL CPU device: " << e.what();
  }
  TempDir dir("viz-data");
  const Scene scene = parseScene(kPanelRoom, dir.path() / "room.yaml");
  const PlotOptions options = panelRoomPlotOptions();
  IlluminanceEngine plotEngine(*device, scene);
  const SurfacesPlot plot = writeSurfacesFile(scene, directLight(plotEngine), options, dir.path());
  // The picture is drawn from the file.
  EXPECT_EQ(drawSurfacesPicture(scene, dir.path() / "surfaces.vtp", "direct light only", options,
                                "room.yaml", dir.path() / "surfaces.png"),
            options.width * 5 / 8);
  EXPECT_EQ(penumbra::testing::Png(dir.path() / "surfaces.png").width(), options.width);

  const SurfaceSamples read = readSurfaceSamples(dir.path() / "surfaces.vtp", scene);
  ASSERT_EQ(read.total, static_cast<vtkIdType>(plot.points));
  const std::vector<SamplePoint>& points = read.points;
  int floorPoints = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const SamplePoint& p = points[k];
    const Vec3& q = p.position;
    // On the floor, in the open, beyond the table's shadow: the closed form applies.
    if (scene.solids[p.solid].name == "room.floor" && p.normal.z() > 0.5 && q.x() > 2.5 &&
        q.x() < 3.8 && q.y() > 2.5 && q.y() < 3.8) {
      const double e = read.illuminance[k];
      EXPECT_NEAR(e, closedForm(q.x(), q.y(), 2.99, 1000.0), 1e-4 * e) << q.transpose();
      EXPECT_NEAR(read.luminance[k], 0.2 * e / std::numbers::pi, 1e-9 * e);
      ++floorPoints;
    }
  }
  EXPECT_GT(floorPoints, 3);
  IlluminanceEngine engine(*device, scene);
  const std::vector<double> expected = engine.illuminance(points);
  int lit = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_EQ(read.illuminance[k], expected[k]) << points[k].position.transpose();
    if (expected[k] > 0.0) ++lit;
  }
  EXPECT_GT(lit, 20);  // not a comparison of zeros
}

// With interreflection the surfaces carry the total: what the run's estimator gives at each
// point (the grids' numbers), at least the direct light everywhere, and light on the ceiling,
// which the downward panel does not reach directly; L = ρ·E/π of the total.
TEST(SurfacesFile, WithInterreflectionTheSurfacesCarryTheTotal) {
  try {
    penumbra::testing::cpuDevice();
  } catch (const std::exception& e) {
    GTEST_SKIP() << "no OpenCL CPU device: " << e.what();
  }
  TempDir dir("viz-data");
  const Scene scene = parseScene(kPanelRoom, dir.path() / "room.yaml");
  EstimatorOptions total;
  total.device = "cpu";
  Estimator plotEstimator(total, scene);
  const PlotOptions options = panelRoomPlotOptions();
  const PointLight light = [&](std::span<const SamplePoint> points) {
    return plotEstimator.illuminance(points).total;
  };
  const SurfacesPlot plot = writeSurfacesFile(scene, light, options, dir.path());
  const SurfaceSamples read = readSurfaceSamples(dir.path() / "surfaces.vtp", scene);
  ASSERT_EQ(read.total, static_cast<vtkIdType>(plot.points));

  Estimator estimator(total, scene);
  const PointIlluminance expected = estimator.illuminance(read.points);
  ASSERT_EQ(expected.direct.size(), read.points.size());
  int ceiling = 0;
  for (std::size_t k = 0; k < read.points.size(); ++k) {
    const SamplePoint& p = read.points[k];
    const double e = read.illuminance[k];
    EXPECT_NEAR(e, expected.total[k], 1e-9 * expected.total[k]) << p.position.transpose();
    EXPECT_GE(e, expected.direct[k]) << p.position.transpose();
    const Vec3& q = p.position;
    const bool inRoom = q.x() > 0.05 && q.x() < 3.95 && q.y() > 0.05 && q.y() < 3.95;
    if (scene.solids[p.solid].name == "room.ceiling" && p.normal.z() < -0.5 && inRoom) {
      EXPECT_EQ(expected.direct[k], 0.0);
      EXPECT_GT(e, 1.0) << p.position.transpose();  // lx, reflected by the floor and walls
      const double rhoY = 0.2126 * 0.8 + 0.7152 * 0.7 + 0.0722 * 0.6;  // paint's luminance factor
      EXPECT_NEAR(read.luminance[k], rhoY * e / std::numbers::pi, 1e-9 * e);
      ++ceiling;
    }
  }
  EXPECT_GT(ceiling, 3);
}

}  // namespace
}  // namespace penumbra::viz
