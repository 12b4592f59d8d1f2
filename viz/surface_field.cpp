#include "viz/surface_field.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace penumbra::viz {

double reflectanceY(const Scene& scene, int solid) {
  const int material = scene.solids.at(solid).material;
  if (material < 0) return std::numeric_limits<double>::quiet_NaN();
  const Vec3& rho = scene.materials.at(material).reflectance;
  return 0.2126 * rho.x() + 0.7152 * rho.y() + 0.0722 * rho.z();
}

vtkSmartPointer<vtkPolyData> surfacePolyData(const Scene& scene, const SurfaceMesh& mesh,
                                             std::span<const double> illuminance) {
  if (illuminance.size() != mesh.points.size()) {
    throw std::invalid_argument("surfacePolyData: one illuminance per point is needed");
  }
  const auto n = static_cast<vtkIdType>(mesh.points.size());
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  auto e = vtkSmartPointer<vtkDoubleArray>::New();
  e->SetName("E_lx");
  e->SetNumberOfTuples(n);
  auto l = vtkSmartPointer<vtkDoubleArray>::New();
  l->SetName("L_cd_m2");
  l->SetNumberOfTuples(n);
  auto normals = vtkSmartPointer<vtkDoubleArray>::New();
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i) {
    const SamplePoint& p = mesh.points[i];
    points->SetPoint(i, p.position.data());
    e->SetValue(i, illuminance[i]);
    l->SetValue(i, reflectanceY(scene, p.solid) * illuminance[i] / std::numbers::pi);
    normals->SetTuple3(i, p.normal.x(), p.normal.y(), p.normal.z());
  }

  auto polygons = vtkSmartPointer<vtkCellArray>::New();
  auto solid = vtkSmartPointer<vtkIntArray>::New();
  solid->SetName("solid");
  auto face = vtkSmartPointer<vtkIntArray>::New();
  face->SetName("face");
  for (std::size_t c = 0; c < mesh.cells.size(); ++c) {
    polygons->InsertNextCell(static_cast<vtkIdType>(mesh.cells[c].size()));
    for (int id : mesh.cells[c]) polygons->InsertCellPoint(id);
    solid->InsertNextValue(mesh.cellSolid[c]);
    face->InsertNextValue(mesh.cellFace[c]);
  }
  auto names = vtkSmartPointer<vtkStringArray>::New();
  names->SetName("solid_names");
  for (const Solid& s : scene.solids) names->InsertNextValue(s.name);

  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(polygons);
  data->GetPointData()->SetScalars(e);
  data->GetPointData()->AddArray(l);
  data->GetPointData()->SetNormals(normals);
  data->GetCellData()->AddArray(solid);
  data->GetCellData()->AddArray(face);
  data->GetFieldData()->AddArray(names);
  return data;
}

}  // namespace penumbra::viz
