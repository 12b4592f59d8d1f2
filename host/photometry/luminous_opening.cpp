#include "photometry/luminous_opening.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace penumbra::photometry {
namespace {

// -1, 0 or +1.
int signOf(double value) {
  return value > 0 ? 1 : (value < 0 ? -1 : 0);
}

bool same(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(a, b);
}

}  // namespace

std::optional<LuminousOpening> openingFromIes(const SignedOpening& dimensions,
                                              double metresPerUnit) {
  LuminousOpening opening;
  opening.widthM = std::abs(dimensions.width) * metresPerUnit;
  opening.lengthM = std::abs(dimensions.length) * metresPerUnit;
  opening.heightM = std::abs(dimensions.height) * metresPerUnit;
  std::fill(std::begin(opening.sideHeightsM), std::end(opening.sideHeightsM), opening.heightM);
  const double w = opening.widthM, l = opening.lengthM, h = opening.heightM;
  const int sw = signOf(dimensions.width), sl = signOf(dimensions.length),
            sh = signOf(dimensions.height);
  using S = OpeningShape;
  if (sw == 0 && sl == 0 && sh == 0) {
    opening.shape = S::Point;
  } else if (sw > 0 && sl > 0 && sh == 0) {
    opening.shape = S::Rectangle;
  } else if (sw > 0 && sl > 0 && sh > 0) {
    opening.shape = S::RectangleWithLuminousSides;
  } else if (sw < 0 && sl == 0 && sh >= 0) {
    // LM-63-1995 files give a round opening by its diameter as a negative width alone.
    opening.lengthM = w;
    opening.shape = sh == 0 ? S::Disk : S::VerticalCylinder;
  } else if (sw < 0 && sl < 0 && sh == 0) {
    opening.shape = same(w, l) ? S::Disk : S::Ellipse;
  } else if (sw < 0 && sl < 0 && sh > 0) {
    opening.shape = same(w, l) ? S::VerticalCylinder : S::VerticalEllipticalCylinder;
  } else if (sw < 0 && sl < 0 && sh < 0) {
    opening.shape = same(w, l) && same(w, h) ? S::Sphere : S::Ellipsoid;
  } else if (sw < 0 && sl > 0 && sh < 0) {
    opening.shape = S::HorizontalCylinderAlongLength;
  } else if (sw > 0 && sl < 0 && sh < 0) {
    opening.shape = S::HorizontalCylinderAlongWidth;
  } else if (sw < 0 && sl == 0 && sh < 0) {
    opening.shape = S::VerticalDiskFacingLength;
  } else if (sw == 0 && sl < 0 && sh < 0) {
    opening.shape = S::VerticalDiskFacingWidth;
  } else {
    return std::nullopt;
  }
  return opening;
}

LuminousOpening openingFromEulumdat(double lengthMm, double widthMm, const double heightsMm[4]) {
  LuminousOpening opening;
  opening.lengthM = lengthMm / 1000;
  double tallest = 0;
  for (int i = 0; i < 4; ++i) {
    opening.sideHeightsM[i] = heightsMm[i] / 1000;
    tallest = std::max(tallest, opening.sideHeightsM[i]);
  }
  opening.heightM = tallest;
  if (lengthMm <= 0) {
    opening.shape = OpeningShape::Point;
    opening.widthM = 0;
  } else if (widthMm <= 0) {
    // EULUMDAT: width 0 means a circular area of diameter `length`.
    opening.widthM = opening.lengthM;
    opening.shape = tallest > 0 ? OpeningShape::VerticalCylinder : OpeningShape::Disk;
  } else {
    opening.widthM = widthMm / 1000;
    opening.shape =
        tallest > 0 ? OpeningShape::RectangleWithLuminousSides : OpeningShape::Rectangle;
  }
  return opening;
}

std::vector<Vec3> flatOutline(const LuminousOpening& opening) {
  const double a = opening.lengthM / 2, b = opening.widthM / 2;
  if (a <= 0 || b <= 0) return {};
  switch (opening.shape) {
    case OpeningShape::Rectangle:
      // Clockwise seen from above: the normal points down.
      return {Vec3(-a, -b, 0), Vec3(-a, b, 0), Vec3(a, b, 0), Vec3(a, -b, 0)};
    case OpeningShape::Disk:
    case OpeningShape::Ellipse: {
      // A regular n-gon inscribed in an ellipse covers n/(2π)·sin(2π/n) of its area.
      const int n = kRoundOpeningSides;
      const double step = 2 * std::numbers::pi / n;
      const double scale = std::sqrt(step / std::sin(step));
      std::vector<Vec3> outline;
      for (int i = 0; i < n; ++i) {
        const double t = -i * step;
        outline.emplace_back(scale * a * std::cos(t), scale * b * std::sin(t), 0);
      }
      return outline;
    }
    default:
      return {};
  }
}

}  // namespace penumbra::photometry
