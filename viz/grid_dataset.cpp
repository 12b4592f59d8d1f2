#include "viz/grid_dataset.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

#include "output/result_files.hpp"
#include "viz/planar_field.hpp"
#include "viz/xml_files.hpp"

namespace penumbra::viz {

namespace {

// The arrays both file kinds carry, in the grid's point order (which is VTK's: x fastest).
void addPointArrays(const GridReport& grid, vtkDataSet* data) {
  const auto n = static_cast<vtkIdType>(grid.points.size());
  auto e = vtkSmartPointer<vtkDoubleArray>::New();
  e->SetName("E_lx");
  e->SetNumberOfTuples(n);
  auto normals = vtkSmartPointer<vtkDoubleArray>::New();
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  auto inside = vtkSmartPointer<vtkUnsignedCharArray>::New();
  inside->SetName("inside_solid");
  inside->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i) {
    e->SetValue(i, grid.illuminance[i]);
    const Vec3& normal = grid.points[i].normal;
    normals->SetTuple3(i, normal.x(), normal.y(), normal.z());
    inside->SetValue(i, grid.insideSolids[i].empty() ? 0 : 1);
  }
  data->GetPointData()->SetScalars(e);
  data->GetPointData()->SetNormals(normals);
  data->GetPointData()->AddArray(inside);
  auto name = vtkSmartPointer<vtkStringArray>::New();
  name->SetName("grid");
  name->InsertNextValue(grid.name);
  data->GetFieldData()->AddArray(name);
}

vtkSmartPointer<vtkImageData> imageData(const GridReport& grid) {
  const PlanarField field = planarField(grid);
  const Vec3 u = field.uStep.normalized(), v = field.vStep.normalized(), n = u.cross(v);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(field.columns, field.rows, 1);
  image->SetOrigin(field.first.x(), field.first.y(), field.first.z());
  image->SetSpacing(field.uStep.norm(), field.vStep.norm(), 1.0);
  // Columns: the directions of the i, j, k axes (a grid on a wall, or turned, stays in place).
  image->SetDirectionMatrix(u.x(), v.x(), n.x(), u.y(), v.y(), n.y(), u.z(), v.z(), n.z());
  addPointArrays(grid, image);
  return image;
}

vtkSmartPointer<vtkPolyData> pointData(const GridReport& grid) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto vertices = vtkSmartPointer<vtkCellArray>::New();
  for (const SamplePoint& p : grid.points) {
    const vtkIdType id = points->InsertNextPoint(p.position.data());
    vertices->InsertNextCell(1, &id);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetVerts(vertices);
  addPointArrays(grid, data);
  return data;
}

}  // namespace

std::string gridDatasetFileName(const GridReport& grid) {
  return gridFileStem(grid.name) + (grid.kind == GridKind::Points ? ".vtp" : ".vti");
}

void writeGridDataset(const GridReport& grid, const std::filesystem::path& file) {
  if (grid.kind == GridKind::Points) {
    writePolyDataFile(pointData(grid), file);
  } else {
    writeImageDataFile(imageData(grid), file);
  }
}

}  // namespace penumbra::viz
