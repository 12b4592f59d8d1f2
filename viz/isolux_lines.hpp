#pragma once
// Isolux lines: where the interpolated illuminance equals a round value.
#include <vector>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

namespace penumbra::viz {

// Round levels for data in [eMin, eMax] lx: the 1-2-5 series (…, 100, 200, 500, 1000, …)
// between them; when that gives fewer than three lines (a uniform field), multiples of a 1-2-5
// step instead (450, 500, 550).
std::vector<double> autoIsoluxLevels(double eMin, double eMax);

// The lines of `surface` (point scalars "E_lx", as fieldSurface makes) at each level, joined
// into polylines, with point scalars "E_lx" equal to their level. Vertices lie on the edges of
// the surface's cells, interpolated linearly along them.
vtkSmartPointer<vtkPolyData> isoluxLines(vtkPolyData* surface, const std::vector<double>& levels);

}  // namespace penumbra::viz
