#pragma once
// The one tolerance policy of penumbra. Every geometric comparison on the host uses
// Tolerance::length (an absolute length derived from the scene's size); the kernel uses
// kKernelRelative on normalised quantities (sines of angles, fractions of a distance).
// Never scatter literals: take them from here.
#include <algorithm>

namespace penumbra {

struct Tolerance {
  // Host geometry is double: 1e-9 of the scene size is far above round-off (1e-16 relative)
  // and far below anything a lighting designer models (a 10 m room: 10 nm).
  static constexpr double kRelativeGeometry = 1e-9;
  // Kernels are float (2^-24 = 6e-8 relative); directions built from differences and cross
  // products lose about two digits, so "on the boundary" means within 1e-5 of a unit quantity.
  static constexpr float kKernelRelative = 1e-5f;
  // Input validation (planarity, convexity, "on its wall") is about what a person typed: 1e-6 of
  // the scene size (a 10 m room: 10 µm).
  static constexpr double kRelativeInput = 1e-6;
  // How far a typed direction (a polygon's `normal`, a grid's u against v) may be from the one
  // the geometry implies, in radians: 0.01 rad (0.6°) accepts normals typed with three decimals
  // and still rejects real mix-ups, which are off by tens of degrees. An angle: not scaled.
  static constexpr double kInputAngle = 1e-2;

  // The thinnest solid the float kernels shade correctly, relative to the scene size: 1e-3
  // (100 × kKernelRelative; a 6 m scene: 6 mm). Thinner slabs put a solid's front and back contour
  // edges within the kernel's tolerance of each other, and points on their shadow boundaries err
  // (bench/degenerate_stress --thin: 0.1 mm 14 %, 1–2 mm up to 20 % at grazing points, 5 mm and
  // 1 cm within the criterion; docs/reliability.md). The loader refuses thinner solids.
  static constexpr double kMinimumThicknessRelative = 1e-3;

  double length = 1e-9;  // absolute length tolerance, metres

  static Tolerance forSceneSize(double sceneSize) {
    return Tolerance{kRelativeGeometry * std::max(sceneSize, 1.0)};
  }
};

}  // namespace penumbra
