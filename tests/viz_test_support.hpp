#pragma once
// What the viz tests share: a PNG read back with VTK, a field with a known shape as a grid run
// would report it, and a small room to draw it in.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include "grid/grid_metrics.hpp"
#include "grid/run_report.hpp"
#include "scene/scene_loader.hpp"

namespace penumbra::testing {

// A PNG as VTK reads it: x to the right, y up from the bottom row (VTK's display coordinates).
class Png {
 public:
  explicit Png(const std::filesystem::path& file) {
    auto reader = vtkSmartPointer<vtkPNGReader>::New();
    reader->SetFileName(file.string().c_str());
    reader->Update();
    image_ = reader->GetOutput();
  }
  int width() const { return image_->GetDimensions()[0]; }
  int height() const { return image_->GetDimensions()[1]; }
  int components() const { return image_->GetNumberOfScalarComponents(); }
  std::array<int, 3> rgb(int x, int y) const {
    const auto* p = static_cast<const unsigned char*>(image_->GetScalarPointer(x, y, 0));
    return {p[0], p[1], p[2]};
  }

 private:
  vtkSmartPointer<vtkImageData> image_;
};

// A 6 × 4 × 3 m room with a window in wall y0, a ceiling panel and a cabinet that stands
// through the work plane.
inline constexpr const char* kRoomScene = R"(penumbra: 1
materials: {grey: 0.5}
room:
  size: [6.0, 4.0, 3.0]
  wall_thickness: 0.2
  materials: {floor: grey, ceiling: grey, walls: grey}
  openings:
    - {name: window, wall: y0, x: 2.0, z: 0.9, width: 2.0, height: 1.5}
solids:
  - {name: cabinet, box: {min: [5.5, 2.8, 0.0], max: [6.0, 3.9, 1.2]}, material: grey}
sources:
  - {name: panel, rect: {center: [3.0, 2.0, 2.99], size: [0.6, 0.6], normal: [0, 0, -1]}, luminance: 3000}
)";

inline Scene roomScene() {
  return parseScene(kRoomScene, "room.yaml");
}

// A known field on a horizontal grid of `columns` × `rows` points `spacing` m apart, the first at
// (x0, y0, 0.8): a smooth hill peaking at (1.9, 1.3) over 200 lx, up to 1200 lx. Values are not
// representable in float (a file that rounds them through float loses them).
inline double hill(double x, double y) {
  return 200.0 + 1000.0 * std::exp(-((x - 1.9) * (x - 1.9) + 0.6 * (y - 1.3) * (y - 1.3)) / 1.7) +
         1.0 / 3.0;
}

inline GridReport hillGrid(int columns = 12, int rows = 8, double spacing = 0.4, double x0 = 0.7,
                           double y0 = 0.6) {
  GridReport grid;
  grid.name = "hill";
  grid.kind = GridKind::Rect;
  grid.columns = columns;
  grid.rows = rows;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      const double x = x0 + spacing * c, y = y0 + spacing * r;
      grid.points.push_back({Vec3(x, y, 0.8), Vec3::UnitZ(), -1});
      grid.illuminance.push_back(hill(x, y));
      grid.insideSolids.emplace_back();
    }
  }
  const std::vector<int> inside(grid.points.size(), -1);
  grid.metrics = gridMetrics(grid.illuminance, inside, spacing);
  return grid;
}

}  // namespace penumbra::testing
