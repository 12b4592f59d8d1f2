#include "photometry/photometric_data.hpp"

namespace penumbra::photometry {

std::string formatName(PhotometricFormat format) {
  return format == PhotometricFormat::Ies ? "IES" : "EULUMDAT";
}

std::string typeName(PhotometricType type) {
  switch (type) {
    case PhotometricType::C:
      return "C";
    case PhotometricType::B:
      return "B";
    case PhotometricType::A:
      return "A";
  }
  return "?";
}

std::string symmetryName(HorizontalSymmetry symmetry) {
  switch (symmetry) {
    case HorizontalSymmetry::Rotational:
      return "rotational (one plane)";
    case HorizontalSymmetry::Quadrant:
      return "quadrant (C0-C90 stored)";
    case HorizontalSymmetry::AboutC0C180:
      return "about the C0-C180 plane (C0-C180 stored)";
    case HorizontalSymmetry::AboutC90C270:
      return "about the C90-C270 plane (C90-C270 stored)";
    case HorizontalSymmetry::None:
      return "none (full circle stored)";
    case HorizontalSymmetry::Lateral:
      return "lateral (H 0-90 stored, I(H) = I(-H))";
  }
  return "?";
}

std::string openingShapeName(OpeningShape shape) {
  switch (shape) {
    case OpeningShape::Point:
      return "point";
    case OpeningShape::Rectangle:
      return "rectangle";
    case OpeningShape::RectangleWithLuminousSides:
      return "rectangle with luminous sides";
    case OpeningShape::Disk:
      return "disk";
    case OpeningShape::Ellipse:
      return "ellipse";
    case OpeningShape::VerticalCylinder:
      return "vertical cylinder";
    case OpeningShape::VerticalEllipticalCylinder:
      return "vertical elliptical cylinder";
    case OpeningShape::Sphere:
      return "sphere";
    case OpeningShape::Ellipsoid:
      return "ellipsoid";
    case OpeningShape::HorizontalCylinderAlongLength:
      return "horizontal cylinder along C0-C180";
    case OpeningShape::HorizontalCylinderAlongWidth:
      return "horizontal cylinder along C90-C270";
    case OpeningShape::VerticalDiskFacingLength:
      return "vertical disk facing C0";
    case OpeningShape::VerticalDiskFacingWidth:
      return "vertical disk facing C90";
  }
  return "?";
}

}  // namespace penumbra::photometry
