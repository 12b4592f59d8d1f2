#pragma once
// The 2-D pieces every picture is annotated with (text, lines, filled shapes), placed in pixels
// from the lower-left corner of the image, VTK's display coordinates.
#include <string>
#include <vector>

#include <vtkActor2D.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <Eigen/Core>

#include "viz/rgb.hpp"

namespace penumbra::viz {

enum class Align { Start, Centre, End };  // left/bottom, centre, right/top

struct TextStyle {
  int size = 18;  // px
  bool bold = false;
  Rgb colour = kInk;
  Align horizontal = Align::Start;
  Align vertical = Align::Start;
  double angle = 0.0;  // degrees, counter-clockwise
  bool box = false;    // a white box behind the text, for labels over colours
};

vtkSmartPointer<vtkTextActor> textAt(const std::string& text, const Eigen::Vector2d& pixel,
                                     const TextStyle& style);

// A polyline through `pixels`; closed joins the last point to the first.
vtkSmartPointer<vtkActor2D> lineAt(const std::vector<Eigen::Vector2d>& pixels, bool closed,
                                   const Rgb& colour, double width);

// The dashes of a polyline through `pixels`: `dash` px drawn, `dash` px left out, in turn along
// its length (the dashes of pixel coordinates, so that they are the same at any scale).
std::vector<std::vector<Eigen::Vector2d>> dashes(const std::vector<Eigen::Vector2d>& pixels,
                                                 bool closed, double dash);

// The polyline through `pixels` drawn dashed (dashes()).
vtkSmartPointer<vtkActor2D> dashedLineAt(const std::vector<Eigen::Vector2d>& pixels, bool closed,
                                         const Rgb& colour, double width, double dash);

// A convex polygon filled with one colour.
vtkSmartPointer<vtkActor2D> fillAt(const std::vector<Eigen::Vector2d>& pixels, const Rgb& colour,
                                   double opacity = 1.0);

// Points on a circle of `radius` px around `centre`, for markers.
std::vector<Eigen::Vector2d> circle(const Eigen::Vector2d& centre, double radius, int sides = 48);

}  // namespace penumbra::viz
