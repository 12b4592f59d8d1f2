#pragma once
// The pinhole camera of a View (Fang ch. 5.2: view parameters and perspective projection) over a
// grid of samples: the image's pixels, each split into subdivisions × subdivisions samples when
// supersampling. Rows run top to bottom.
#include <optional>

#include <Eigen/Core>

#include "scene/scene.hpp"

namespace penumbra {

struct Camera {
  Vec3 eye = Vec3::Zero();
  Vec3 forward = Vec3::UnitX();  // unit, along the line of sight
  // Perpendicular to forward, scaled so that forward ± right and forward ± up are the rays
  // through the image's left/right and top/bottom edges.
  Vec3 right = Vec3::UnitY(), up = Vec3::UnitZ();
  int width = 1, height = 1;  // samples

  // `subdivisions` samples per pixel side (1: one sample at each pixel's centre).
  static Camera forView(const View& view, int subdivisions = 1);

  // The (unnormalised) ray direction through the centre of sample (x, y): forward + sx·right +
  // sy·up. The kernel computes the same expression in float.
  Vec3 direction(int x, int y) const;
  // Continuous sample coordinates of a point in front of the eye (the centre of sample (x, y) is
  // at (x + 0.5, y + 0.5)) and its depth along forward; nullopt for depth <= minDepth.
  std::optional<Eigen::Vector2d> project(const Vec3& point, double minDepth) const;
  double depth(const Vec3& point) const { return forward.dot(point - eye); }
};

}  // namespace penumbra
