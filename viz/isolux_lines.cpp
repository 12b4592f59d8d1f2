#include "viz/isolux_lines.hpp"

#include <vtkContourFilter.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkStripper.h>

#include <algorithm>
#include <cmath>

#include "viz/nice_numbers.hpp"

namespace penumbra::viz {

std::vector<double> autoIsoluxLevels(double eMin, double eMax) {
  if (!std::isfinite(eMin) || !std::isfinite(eMax) || !(eMax > eMin)) return {};
  std::vector<double> levels = oneTwoFiveBetween(eMin, eMax);
  if (levels.size() >= 3) return levels;
  levels.clear();
  for (double v : multiplesOf(oneTwoFiveAtLeast((eMax - eMin) / 6), eMin, eMax)) {
    if (v > eMin && v < eMax) levels.push_back(v);
  }
  return levels;
}

vtkSmartPointer<vtkPolyData> isoluxLines(vtkPolyData* surface, const std::vector<double>& levels) {
  auto contour = vtkSmartPointer<vtkContourFilter>::New();
  contour->SetInputData(surface);
  contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "E_lx");
  contour->SetNumberOfContours(static_cast<int>(levels.size()));
  for (std::size_t i = 0; i < levels.size(); ++i) contour->SetValue(static_cast<int>(i), levels[i]);
  contour->ComputeScalarsOn();
  contour->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  // Pieces of one line meet at cell edges; joined, a line can carry one label.
  auto stripper = vtkSmartPointer<vtkStripper>::New();
  stripper->SetInputConnection(contour->GetOutputPort());
  stripper->JoinContiguousSegmentsOn();
  stripper->Update();
  vtkSmartPointer<vtkPolyData> lines = stripper->GetOutput();
  // Interpolation leaves the scalars a few ulps off their level: give each its level exactly.
  if (vtkDataArray* scalars = lines->GetPointData()->GetScalars()) {
    for (vtkIdType i = 0; i < scalars->GetNumberOfTuples(); ++i) {
      const double value = scalars->GetTuple1(i);
      const auto nearest = std::min_element(levels.begin(), levels.end(), [&](double a, double b) {
        return std::abs(a - value) < std::abs(b - value);
      });
      scalars->SetTuple1(i, *nearest);
    }
  }
  return lines;
}

}  // namespace penumbra::viz
