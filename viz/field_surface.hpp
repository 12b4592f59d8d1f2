#pragma once
// The heat map's surface: the planar field resampled finely in plot coordinates, so that the
// colours and the isolux lines follow the bilinear interpolation of the grid (as a lighting
// program draws it) rather than VTK's split of each cell into two triangles.
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "viz/planar_field.hpp"

namespace penumbra::viz {

// E at grid coordinates (a, b): bilinear between the four surrounding points, constant beyond the
// outer points (the half cell between them and the edge of the calculation area).
double bilinearIlluminance(const PlanarField& field, double a, double b);

// Sub-divisions per grid step: even, so that the fine lattice holds every grid point and the
// edges of the calculation area; about 400 fine cells along the longer side.
int fieldSubdivisions(const PlanarField& field);

// Quads over the calculation area (half a step beyond the outer points) in plot coordinates
// (z = 0), with point scalars "E_lx". Cells that would interpolate from a point inside a solid are
// left out: there is no illuminance there to show.
vtkSmartPointer<vtkPolyData> fieldSurface(const PlanarField& field, int subdivisions);

}  // namespace penumbra::viz
