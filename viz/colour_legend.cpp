#include "viz/colour_legend.hpp"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkUnsignedCharArray.h>

#include "viz/overlay.hpp"

namespace penumbra::viz {

namespace {

// The bar as 256 bands, each in the colour the lookup table gives the band's middle: the
// legend shows exactly the colours of the picture.
vtkSmartPointer<vtkActor2D> colourBar(const ColourScale& scale, const LegendPlacement& at) {
  constexpr int kBands = 256;
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto bands = vtkSmartPointer<vtkCellArray>::New();
  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetNumberOfComponents(3);
  for (int i = 0; i <= kBands; ++i) {
    const double y = at.y + at.height * i / kBands;
    points->InsertNextPoint(at.x, y, 0.0);
    points->InsertNextPoint(at.x + at.width, y, 0.0);
  }
  for (int i = 0; i < kBands; ++i) {
    const vtkIdType quad[4] = {2 * i, 2 * i + 1, 2 * i + 3, 2 * i + 2};
    bands->InsertNextCell(4, quad);
    const Rgb c = paletteColour(scale.palette, (i + 0.5) / kBands);
    colours->InsertNextTuple3(255.0 * c[0] + 0.5, 255.0 * c[1] + 0.5, 255.0 * c[2] + 0.5);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(bands);
  data->GetCellData()->SetScalars(colours);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
  mapper->SetInputData(data);
  mapper->SetColorModeToDirectScalars();
  mapper->SetScalarModeToUseCellData();
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  return actor;
}

}  // namespace

void addColourLegend(vtkRenderer* renderer, const ColourScale& scale, const LegendPlacement& at,
                     const std::string& title, const std::vector<double>& marks) {
  using V = Eigen::Vector2d;
  const double f = at.fontScale;
  renderer->AddActor2D(colourBar(scale, at));
  const V corner{at.x, at.y};
  renderer->AddActor2D(lineAt({corner,
                               {at.x + at.width, at.y},
                               {at.x + at.width, at.y + at.height},
                               {at.x, at.y + at.height}},
                              true, kInk, 1.2 * f));
  // Isolux levels across the bar, so that a line on the picture can be read off the legend.
  for (double level : marks) {
    const double y = at.y + at.height * scale.fraction(level);
    renderer->AddActor2D(lineAt({{at.x, y}, {at.x + at.width, y}}, false, kInk, 1.5 * f));
  }

  TextStyle label;
  label.size = static_cast<int>(18 * f + 0.5);
  label.vertical = Align::Centre;
  for (double tick : legendTicks(scale)) {
    const double y = at.y + at.height * scale.fraction(tick);
    renderer->AddActor2D(
        lineAt({{at.x + at.width, y}, {at.x + at.width + 7 * f, y}}, false, kInk, 1.2 * f));
    renderer->AddActor2D(textAt(tickLabel(scale, tick), {at.x + at.width + 11 * f, y}, label));
  }

  TextStyle heading;
  heading.size = static_cast<int>(20 * f + 0.5);
  heading.bold = true;
  const double top = at.y + at.height + 16 * f;
  if (scale.log) {
    TextStyle note = label;
    note.vertical = Align::Start;
    note.size = static_cast<int>(16 * f + 0.5);
    renderer->AddActor2D(textAt("logarithmic scale", {at.x, top}, note));
    renderer->AddActor2D(textAt(title, {at.x, top + 24 * f}, heading));
  } else {
    renderer->AddActor2D(textAt(title, {at.x, top}, heading));
  }
}

}  // namespace penumbra::viz
