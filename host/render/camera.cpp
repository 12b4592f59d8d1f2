#include "render/camera.hpp"

#include <cmath>
#include <numbers>

namespace penumbra {

Camera Camera::forView(const View& view, int subdivisions) {
  Camera camera;
  camera.eye = view.eye;
  camera.forward = (view.target - view.eye).normalized();
  // The scene loader has checked that up is not along the line of sight.
  const Vec3 rightUnit = camera.forward.cross(view.up).normalized();
  const Vec3 upUnit = rightUnit.cross(camera.forward);
  camera.width = view.width * subdivisions;
  camera.height = view.height * subdivisions;
  const double halfWidth = std::tan(view.fovDegrees * std::numbers::pi / 360.0);
  // Square pixels: the vertical half-angle follows from the aspect ratio.
  const double halfHeight = halfWidth * view.height / view.width;
  camera.right = halfWidth * rightUnit;
  camera.up = halfHeight * upUnit;
  return camera;
}

Vec3 Camera::direction(int x, int y) const {
  const double sx = 2.0 * (x + 0.5) / width - 1.0;
  const double sy = 1.0 - 2.0 * (y + 0.5) / height;
  return forward + sx * right + sy * up;
}

std::optional<Eigen::Vector2d> Camera::project(const Vec3& point, double minDepth) const {
  const Vec3 d = point - eye;
  const double z = forward.dot(d);
  if (z <= minDepth) return std::nullopt;
  const double sx = right.dot(d) / (z * right.squaredNorm());
  const double sy = up.dot(d) / (z * up.squaredNorm());
  return Eigen::Vector2d((sx + 1.0) * 0.5 * width, (1.0 - sy) * 0.5 * height);
}

}  // namespace penumbra
