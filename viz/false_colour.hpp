#pragma once
// A surface in false colour: its point scalars mapped through the scale's lookup table,
// interpolated before mapping (colours follow the values, not a blend of corner colours) and
// unlit (every pixel has exactly a colour of the legend).
#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include "viz/colour_scale.hpp"

namespace penumbra::viz {

vtkSmartPointer<vtkActor> falseColourActor(vtkPolyData* data, const ColourScale& scale);

// Lines or polygons in one colour, unlit.
vtkSmartPointer<vtkActor> plainActor(vtkPolyData* data, const Rgb& colour, double lineWidth);

}  // namespace penumbra::viz
