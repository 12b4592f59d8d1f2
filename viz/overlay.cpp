#include "viz/overlay.hpp"

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "viz/fonts.hpp"

namespace penumbra::viz {

namespace {

vtkSmartPointer<vtkActor2D> actorFor(const std::vector<Eigen::Vector2d>& pixels,
                                     vtkCellArray* cells, bool asLines) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (const Eigen::Vector2d& p : pixels) points->InsertNextPoint(p.x(), p.y(), 0.0);
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  if (asLines) {
    data->SetLines(cells);
  } else {
    data->SetPolys(cells);
  }
  auto mapper = vtkSmartPointer<vtkPolyDataMapper2D>::New();
  mapper->SetInputData(data);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor2D>::New();
  actor->SetMapper(mapper);
  return actor;
}

int vtkJustification(Align align) {
  switch (align) {
    case Align::Start:
      return VTK_TEXT_LEFT;  // == VTK_TEXT_BOTTOM
    case Align::Centre:
      return VTK_TEXT_CENTERED;
    case Align::End:
      return VTK_TEXT_RIGHT;  // == VTK_TEXT_TOP
  }
  return VTK_TEXT_LEFT;
}

}  // namespace

vtkSmartPointer<vtkTextActor> textAt(const std::string& text, const Eigen::Vector2d& pixel,
                                     const TextStyle& style) {
  auto actor = vtkSmartPointer<vtkTextActor>::New();
  actor->SetInput(text.c_str());
  vtkTextProperty* p = actor->GetTextProperty();
  useLabelFont(p, style.bold);
  p->SetFontSize(style.size);
  p->SetColor(style.colour[0], style.colour[1], style.colour[2]);
  p->SetJustification(vtkJustification(style.horizontal));
  p->SetVerticalJustification(vtkJustification(style.vertical));
  p->SetOrientation(style.angle);
  if (style.box) {
    p->SetBackgroundColor(1.0, 1.0, 1.0);
    p->SetBackgroundOpacity(0.85);
  }
  actor->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
  actor->GetPositionCoordinate()->SetValue(pixel.x(), pixel.y());
  return actor;
}

vtkSmartPointer<vtkActor2D> lineAt(const std::vector<Eigen::Vector2d>& pixels, bool closed,
                                   const Rgb& colour, double width) {
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  const auto n = static_cast<vtkIdType>(pixels.size());
  cells->InsertNextCell(closed ? n + 1 : n);
  for (vtkIdType i = 0; i < n; ++i) cells->InsertCellPoint(i);
  if (closed) cells->InsertCellPoint(0);
  auto actor = actorFor(pixels, cells, true);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  return actor;
}

std::vector<std::vector<Eigen::Vector2d>> dashes(const std::vector<Eigen::Vector2d>& pixels,
                                                 bool closed, double dash) {
  std::vector<Eigen::Vector2d> path = pixels;
  if (closed && !pixels.empty()) path.push_back(pixels.front());
  std::vector<std::vector<Eigen::Vector2d>> pieces;
  if (path.size() < 2 || !(dash > 0.0)) return pieces;
  pieces.push_back({path.front()});
  bool drawing = true;
  double left = dash;  // of the current dash or gap
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    Eigen::Vector2d at = path[i];
    double segment = (path[i + 1] - at).norm();
    const Eigen::Vector2d step =
        segment > 0.0 ? Eigen::Vector2d((path[i + 1] - at) / segment) : Eigen::Vector2d::Zero();
    while (segment > 0.0) {
      const double run = std::min(left, segment);
      at += run * step;
      segment -= run;
      left -= run;
      if (drawing) pieces.back().push_back(at);
      if (left <= 0.0) {
        drawing = !drawing;
        left = dash;
        if (drawing) pieces.push_back({at});
      }
    }
  }
  std::erase_if(pieces, [](const std::vector<Eigen::Vector2d>& p) { return p.size() < 2; });
  return pieces;
}

vtkSmartPointer<vtkActor2D> dashedLineAt(const std::vector<Eigen::Vector2d>& pixels, bool closed,
                                         const Rgb& colour, double width, double dash) {
  std::vector<Eigen::Vector2d> points;
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (const std::vector<Eigen::Vector2d>& piece : dashes(pixels, closed, dash)) {
    cells->InsertNextCell(static_cast<vtkIdType>(piece.size()));
    for (const Eigen::Vector2d& p : piece) {
      cells->InsertCellPoint(static_cast<vtkIdType>(points.size()));
      points.push_back(p);
    }
  }
  auto actor = actorFor(points, cells, true);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  return actor;
}

vtkSmartPointer<vtkActor2D> fillAt(const std::vector<Eigen::Vector2d>& pixels, const Rgb& colour,
                                   double opacity) {
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->InsertNextCell(static_cast<vtkIdType>(pixels.size()));
  for (vtkIdType i = 0; i < static_cast<vtkIdType>(pixels.size()); ++i) cells->InsertCellPoint(i);
  auto actor = actorFor(pixels, cells, false);
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  actor->GetProperty()->SetOpacity(opacity);
  return actor;
}

std::vector<Eigen::Vector2d> circle(const Eigen::Vector2d& centre, double radius, int sides) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < sides; ++i) {
    const double a = 2.0 * std::numbers::pi * i / sides;
    points.emplace_back(centre.x() + radius * std::cos(a), centre.y() + radius * std::sin(a));
  }
  return points;
}

}  // namespace penumbra::viz
