#include "viz/field_surface.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <algorithm>
#include <cmath>

namespace penumbra::viz {

namespace {

// Along one grid direction with n points: the lower neighbour i0, the upper i1 and the weight of
// i1, for a coordinate clamped to the outer points.
struct Bracket {
  int i0 = 0, i1 = 0;
  double weight = 0.0;
};

Bracket bracket(double a, int n) {
  if (n == 1) return {};
  const double clamped = std::clamp(a, 0.0, static_cast<double>(n - 1));
  const int i0 = std::min(static_cast<int>(std::floor(clamped)), n - 2);
  return {i0, i0 + 1, clamped - i0};
}

}  // namespace

double bilinearIlluminance(const PlanarField& f, double a, double b) {
  const Bracket u = bracket(a, f.columns), v = bracket(b, f.rows);
  const auto e = [&](int c, int r) { return f.illuminance[f.index(c, r)]; };
  return (1 - u.weight) * (1 - v.weight) * e(u.i0, v.i0) +
         u.weight * (1 - v.weight) * e(u.i1, v.i0) + (1 - u.weight) * v.weight * e(u.i0, v.i1) +
         u.weight * v.weight * e(u.i1, v.i1);
}

int fieldSubdivisions(const PlanarField& f) {
  constexpr int kFineCells = 400;
  const int longer = std::max(f.columns, f.rows);
  return std::max(2, 2 * ((kFineCells / 2 + longer - 1) / longer));
}

vtkSmartPointer<vtkPolyData> fieldSurface(const PlanarField& f, int k) {
  const int nu = k * f.columns + 1, nv = k * f.rows + 1;
  const auto gridCoordinate = [k](int j) { return -0.5 + static_cast<double>(j) / k; };

  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(nu) * nv);
  auto scalars = vtkSmartPointer<vtkDoubleArray>::New();
  scalars->SetName("E_lx");
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(nu) * nv);
  for (int i = 0; i < nv; ++i) {
    for (int j = 0; j < nu; ++j) {
      const double a = gridCoordinate(j), b = gridCoordinate(i);
      const Eigen::Vector2d st = f.plotAt(a, b);
      const vtkIdType id = static_cast<vtkIdType>(i) * nu + j;
      points->SetPoint(id, st.x(), st.y(), 0.0);
      scalars->SetValue(id, bilinearIlluminance(f, a, b));
    }
  }

  const auto isValid = [&](int c, int r) { return f.valid[f.index(c, r)] != 0; };
  auto quads = vtkSmartPointer<vtkCellArray>::New();
  for (int i = 0; i + 1 < nv; ++i) {
    const Bracket v = bracket(gridCoordinate(i) + 0.5 / k, f.rows);
    for (int j = 0; j + 1 < nu; ++j) {
      const Bracket u = bracket(gridCoordinate(j) + 0.5 / k, f.columns);
      if (!isValid(u.i0, v.i0) || !isValid(u.i1, v.i0) || !isValid(u.i0, v.i1) ||
          !isValid(u.i1, v.i1)) {
        continue;
      }
      const vtkIdType corner = static_cast<vtkIdType>(i) * nu + j;
      const vtkIdType quad[4] = {corner, corner + 1, corner + nu + 1, corner + nu};
      quads->InsertNextCell(4, quad);
    }
  }
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(quads);
  surface->GetPointData()->SetScalars(scalars);
  return surface;
}

}  // namespace penumbra::viz
