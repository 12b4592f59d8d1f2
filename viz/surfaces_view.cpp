#include "viz/surfaces_view.hpp"

#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "viz/colour_legend.hpp"
#include "viz/cutaway.hpp"
#include "viz/false_colour.hpp"
#include "viz/overlay.hpp"
#include "viz/render_png.hpp"

namespace penumbra::viz {

namespace {

constexpr Rgb kEdge{0.25, 0.25, 0.25};
constexpr Rgb kSourceFill{1.0, 0.97, 0.82};
// Legend and margins at 1600 px wide, scaled with the width.
constexpr double kRightMargin = 270.0;
constexpr double kTopMargin = 130.0;

// The cells of the solids the view keeps (same points and point arrays).
vtkSmartPointer<vtkPolyData> visibleCells(vtkPolyData* surfaces, const Cutaway& view) {
  auto solid = vtkIntArray::SafeDownCast(surfaces->GetCellData()->GetArray("solid"));
  auto kept = vtkSmartPointer<vtkCellArray>::New();
  vtkCellArray* polys = surfaces->GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  vtkIdType cell = 0;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids); ++cell) {
    const int s = solid != nullptr ? solid->GetValue(cell) : -1;
    if (s < 0 || s >= static_cast<int>(view.hidden.size()) || !view.hidden[s]) {
      kept->InsertNextCell(count, ids);
    }
  }
  auto visible = vtkSmartPointer<vtkPolyData>::New();
  visible->SetPoints(surfaces->GetPoints());
  visible->GetPointData()->ShallowCopy(surfaces->GetPointData());
  visible->SetPolys(kept);
  return visible;
}

// Polygons as closed lines (or filled), each moved `lift` m along its normal so that it is not
// hidden in the surface it lies on.
vtkSmartPointer<vtkPolyData> polygonsData(const std::vector<ConvexPolygon>& polygons, double lift,
                                          bool filled) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (const ConvexPolygon& polygon : polygons) {
    const Vec3 offset = lift * polygon.normal();
    const vtkIdType first = points->GetNumberOfPoints();
    for (const Vec3& v : polygon.vertices()) {
      const Vec3 lifted = v + offset;
      points->InsertNextPoint(lifted.data());
    }
    const auto n = static_cast<vtkIdType>(polygon.vertices().size());
    cells->InsertNextCell(filled ? n : n + 1);
    for (vtkIdType i = 0; i < n; ++i) cells->InsertCellPoint(first + i);
    if (!filled) cells->InsertCellPoint(first);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  if (filled) {
    data->SetPolys(cells);
  } else {
    data->SetLines(cells);
  }
  return data;
}

// Where a world point lands on the image, in normalised device coordinates ([-1, 1] across and
// up), for a camera at `eye` looking along `forward`.
Eigen::Vector2d projectToNdc(const Vec3& p, const Vec3& eye, const Vec3& forward, const Vec3& right,
                             const Vec3& up, double tanHalfAngle, double aspect) {
  const Vec3 r = p - eye;
  const double depth = r.dot(forward);
  return {r.dot(right) / (depth * tanHalfAngle * aspect), r.dot(up) / (depth * tanHalfAngle)};
}

// Places the camera on the cutaway's direction at the distance where the framed box just fills
// the space left of the legend and under the title, and centres it there.
void fitCamera(vtkCamera* camera, const Cutaway& view, int width, int height, double f) {
  constexpr double kViewAngle = 30.0;  // degrees, vertical: a natural perspective
  const Vec3 centre = 0.5 * (view.lo + view.hi);
  const Vec3 forward = -view.fromFocus;
  const Vec3 right = forward.cross(Vec3::UnitZ()).normalized();
  const Vec3 up = right.cross(forward);
  const double aspect = static_cast<double>(width) / height;
  const double t = std::tan(kViewAngle * std::numbers::pi / 360.0);
  // The target, in normalised device coordinates.
  const Eigen::Vector2d lo{-1.0 + 2.0 * 30 * f / width, -1.0 + 2.0 * 30 * f / height};
  const Eigen::Vector2d hi{1.0 - 2.0 * kRightMargin * f / width,
                           1.0 - 2.0 * kTopMargin * f / height};
  std::vector<Vec3> corners;
  for (int i = 0; i < 8; ++i) {
    corners.emplace_back(i & 1 ? view.hi.x() : view.lo.x(), i & 2 ? view.hi.y() : view.lo.y(),
                         i & 4 ? view.hi.z() : view.lo.z());
  }
  const auto extent = [&](double distance, Eigen::Vector2d& min, Eigen::Vector2d& max) {
    const Vec3 eye = centre - distance * forward;
    min = Eigen::Vector2d::Constant(INFINITY);
    max = -min;
    for (const Vec3& c : corners) {
      const Eigen::Vector2d p = projectToNdc(c, eye, forward, right, up, t, aspect);
      min = min.cwiseMin(p);
      max = max.cwiseMax(p);
    }
  };
  // The projected size shrinks as the camera backs away: bisect for the distance that fits.
  const double size = (view.hi - view.lo).norm();
  double near = 0.6 * size, far = 50.0 * size;
  Eigen::Vector2d min, max;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (near + far);
    extent(mid, min, max);
    const Eigen::Vector2d span = max - min;
    const bool fits = span.x() <= hi.x() - lo.x() && span.y() <= hi.y() - lo.y();
    (fits ? far : near) = mid;
  }
  extent(far, min, max);
  const Vec3 eye = centre - far * forward;
  camera->SetFocalPoint(centre.data());
  camera->SetPosition(eye.data());
  camera->SetViewUp(up.data());
  camera->SetViewAngle(kViewAngle);
  // Shifting the window centre moves the picture without turning the camera.
  const Eigen::Vector2d shift = 0.5 * (min + max) - 0.5 * (lo + hi);
  camera->SetWindowCenter(shift.x(), shift.y());
}

}  // namespace

int drawSurfaces(const Scene& scene, vtkPolyData* surfaces, const SurfacesStyle& style,
                 const std::filesystem::path& png) {
  const Cutaway view = chooseCutaway(scene);
  const int width = style.width;
  const int height = width * 5 / 8;
  const double f = width / 1600.0;
  const double lift = 2e-3 * (view.hi - view.lo).norm();

  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(1.0, 1.0, 1.0);
  vtkSmartPointer<vtkActor> colours = falseColourActor(visibleCells(surfaces, view), style.scale);
  // Seen from outside, a face turned away is the back of a slab: not drawn, so that the room
  // is seen into, not its outer skin.
  colours->GetProperty()->BackfaceCullingOn();
  renderer->AddActor(colours);

  std::vector<ConvexPolygon> edges;
  for (std::size_t s = 0; s < scene.solids.size(); ++s) {
    if (view.hidden[s]) continue;
    const ConvexPolyhedron& shape = scene.solids[s].shape;
    for (int face = 0; face < static_cast<int>(shape.faces().size()); ++face) {
      edges.push_back(shape.facePolygon(face));
    }
  }
  vtkSmartPointer<vtkActor> outlines = plainActor(polygonsData(edges, lift, false), kEdge, 1.2 * f);
  outlines->GetProperty()->BackfaceCullingOn();
  renderer->AddActor(outlines);

  std::vector<ConvexPolygon> sources;
  for (const Source& source : scene.sources) {
    sources.insert(sources.end(), source.faces.begin(), source.faces.end());
  }
  renderer->AddActor(plainActor(polygonsData(sources, lift, true), kSourceFill, 1.0));
  renderer->AddActor(plainActor(polygonsData(sources, 1.5 * lift, false), kSourceEdge, 2.0 * f));

  fitCamera(renderer->GetActiveCamera(), view, width, height, f);
  renderer->ResetCameraClippingRange();

  TextStyle title;
  title.size = static_cast<int>(26 * f + 0.5);
  title.bold = true;
  title.vertical = Align::End;
  const double x = 40 * f;
  renderer->AddActor2D(textAt("Room surfaces: illuminance E", {x, height - 20 * f}, title));
  TextStyle note = title;
  note.size = static_cast<int>(19 * f + 0.5);
  note.bold = false;
  if (!view.note.empty()) {
    renderer->AddActor2D(
        textAt("Left out of the view: " + view.note + " (surfaces.vtp has every face)",
               {x, height - 58 * f}, note));
  }
  note.size = static_cast<int>(16 * f + 0.5);
  note.colour = kSubtle;
  renderer->AddActor2D(textAt(style.subtitle, {x, height - 90 * f}, note));

  LegendPlacement legend;
  legend.fontScale = f;
  legend.x = width - 230 * f;
  legend.y = 60 * f;
  legend.width = 30 * f;
  legend.height = height - 60 * f - 200 * f;
  addColourLegend(renderer, style.scale, legend, "Illuminance E [lx]");

  renderToPng(renderer, width, height, png);
  return height;
}

}  // namespace penumbra::viz
