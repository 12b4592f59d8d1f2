#pragma once
// The one tolerance policy of penumbra. Every geometric comparison on the host uses
// Tolerance::length (an absolute length derived from the scene's size); the kernel uses
// kKernelRelative on normalised quantities (sines of angles, fractions of a distance) and
// kernelLength on lengths (a multiple of float's resolution where the point is).
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
  // The tie rule's tolerance (kernels/contour.cl, docs/method.md "The tie rule"): an edge lies in
  // another's side plane where both its ends are within 1e-6 (sine) of it. A side plane through
  // P is good to a few 1e-7 (vectors from P's double-float position, one cross product,
  // normalised), so edges that coincide in the scene stay tied; a real gap wider than 1e-6 is
  // integrated as it is. Whatever the rule keeps or drops lies within that band, so it is
  // tighter than kKernelRelative: a bezel's lip seen from 15-25° below a panel's plane errs by
  // 2-4e-5 of E at 1e-6, against 1e-4 at 1e-5.
  static constexpr float kKernelTie = 1e-6f;
  // Input validation (planarity, convexity, "on its wall") is about what a person typed: 1e-6 of
  // the scene size (a 10 m room: 10 µm).
  static constexpr double kRelativeInput = 1e-6;
  // How far a typed direction (a polygon's `normal`, a grid's u against v) may be from the one
  // the geometry implies, in radians: 0.01 rad (0.6°) accepts normals typed with three decimals
  // and still rejects real mix-ups, which are off by tens of degrees. An angle: not scaled.
  static constexpr double kInputAngle = 1e-2;

  // The kernel's length tolerance at a point (plane heights, "P lies on this face"): what float
  // resolves there, not a fraction of the scene. Positions reach the kernel relative to its origin
  // (the centre of the scene's geometry, engine/kernel_scene.cpp), so a plane height at P is good
  // to a few roundings of P's largest coordinate r (2^-24 = 6e-8 relative each: the point's and
  // the plane's rounding and the dot product's, at most about 6e-7·r). The tolerance is 1e-6·r,
  // and 1e-6 m within 1 m of the origin, where roundings of 1 m-sized vectors still enter:
  // 1 µm at the centre, 50 µm at 50 m from it.
  static constexpr double kKernelLengthRelative = 1e-6;
  static constexpr double kKernelLengthReach = 1.0;  // m: the floor of r above

  // The thinnest solid the kernels shade correctly, in kernel length tolerances at the solid's
  // place: 100. A point closer than the tolerance to a face counts as on it, and the face then
  // hides its whole half-space; beside a slab only a few tolerances thick that misjudges the
  // source seen past the slab's edges. The stress suite's thin boxes hold its criterion at 85
  // and 170 tolerances and fail it at 34 and below (bench/degenerate_stress --thin,
  // docs/reliability.md). At 50 m from the scene's centre: 5 mm; within 1 m of it: 0.1 mm. The
  // loader refuses thinner solids.
  static constexpr double kMinimumThicknessInKernelTolerances = 100.0;

  // The kernel's length tolerance (m) at a point whose largest coordinate relative to the
  // kernel's origin is `reach` (m).
  static double kernelLength(double reach) {
    return kKernelLengthRelative * std::max(reach, kKernelLengthReach);
  }
  // The thinnest solid (m) the kernels shade correctly where its farthest vertex lies `reach` (m,
  // largest coordinate) from the kernel's origin.
  static double minimumThickness(double reach) {
    return kMinimumThicknessInKernelTolerances * kernelLength(reach);
  }

  double length = 1e-9;  // absolute length tolerance, metres

  static Tolerance forSceneSize(double sceneSize) {
    return Tolerance{kRelativeGeometry * std::max(sceneSize, 1.0)};
  }
};

}  // namespace penumbra
