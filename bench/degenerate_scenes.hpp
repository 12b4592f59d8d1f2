#pragma once
// Degenerate configurations for the stress suite (docs/reliability.md), generated from a seed so
// that a failure is reproduced by its number. Coordinates are drawn on a coarse lattice, so that
// the coincidences a designer's model is full of happen all the time instead of never: occluders
// touching each other or sharing an edge, touching or crossing the source's plane, standing flush
// on the receiving floor, with edges collinear to source edges; zero-thickness and thin
// boxes; points exactly on shadow boundaries (a source vertex projected through an occluder
// vertex onto the floor); points in the source's plane (the source seen edge-on).
#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "geometry/sample_point.hpp"
#include "scene/scene.hpp"

namespace penumbra::bench {

struct DegenerateCase {
  Scene scene;
  std::vector<SamplePoint> points;
  std::string description;  // what was drawn, to reproduce a failure by hand
};

class DegenerateGenerator {
 public:
  // The thickness of the "thin" boxes: 1 cm holds the stress criterion; thinner ones approach
  // the kernel's length tolerance (Tolerance::kernelLength: 1e-6 of the distance from the
  // scene's centre, a few µm here) and are explored with `degenerate_stress --thin`
  // (docs/reliability.md).
  static constexpr double kThinBox = 1e-2;  // m

  explicit DegenerateGenerator(std::uint64_t seed, double thin = kThinBox)
      : random_(seed), thin_(thin) {}

  // Configuration number `index` of this seed's sequence (deterministic: each has its own
  // generator state derived from seed and index, so a failing one is rebuilt alone).
  static DegenerateCase make(std::uint64_t seed, std::uint64_t index, double thin = kThinBox) {
    DegenerateGenerator g(seed * 0x9E3779B97F4A7C15ull + index, thin);
    DegenerateCase c = g.build();
    c.description = fmt::format("seed {} configuration {}: {}", seed, index, c.description);
    return c;
  }

 private:
  static constexpr double kStep = 0.25;   // lattice, m
  static constexpr double kHeight = 2.0;  // ceiling sources, m

  // Uniform in [0, 1), the same on every platform (std::uniform_*_distribution are not).
  double unit() { return static_cast<double>(random_() >> 11) * 0x1.0p-53; }
  int integer(int lo, int hi) { return lo + static_cast<int>(unit() * (hi - lo + 1)); }
  double lattice(int lo, int hi) { return kStep * integer(lo, hi); }
  bool chance(double p) { return unit() < p; }

  DegenerateCase build() {
    DegenerateCase c;
    const bool window = chance(0.3);
    Vec3 corner[4];
    if (window) {
      // A window in the wall x = -2 facing +x; its sill may lie in the floor's plane (the floor
      // sees it edge-on).
      const double y0 = lattice(-6, 2), y1 = y0 + lattice(1, 6);
      const double z0 = lattice(0, 3), z1 = z0 + lattice(1, 5);
      corner[0] = {-2, y0, z0}, corner[1] = {-2, y1, z0}, corner[2] = {-2, y1, z1},
      corner[3] = {-2, y0, z1};  // counter-clockwise about +x
    } else {
      const double x0 = lattice(-6, 2), x1 = x0 + lattice(1, 6);
      const double y0 = lattice(-6, 2), y1 = y0 + lattice(1, 6);
      corner[0] = {x0, y0, kHeight}, corner[1] = {x0, y1, kHeight}, corner[2] = {x1, y1, kHeight},
      corner[3] = {x1, y0, kHeight};  // counter-clockwise about -z
    }
    Source source;
    source.name = "source";
    source.faces.push_back(ConvexPolygon({corner[0], corner[1], corner[2], corner[3]}));
    source.luminance = 1000.0;
    c.scene.sources.push_back(source);
    c.description = fmt::format("{} source [{}..{}] x [{}..{}] x [{}..{}]",
                                window ? "window" : "ceiling", corner[0].x(), corner[2].x(),
                                corner[0].y(), corner[2].y(), corner[0].z(), corner[2].z());

    const int boxes = integer(1, 3);
    for (int b = 0; b < boxes; ++b) addBox(c, corner, window);
    addPoints(c, corner, window);
    return c;
  }

  void addBox(DegenerateCase& c, const Vec3 corner[4], bool window) {
    Vec3 lo(lattice(-8, 6), lattice(-8, 6), lattice(0, 6));
    Vec3 hi = lo + Vec3(lattice(1, 4), lattice(1, 4), lattice(1, 4));
    const int kind = integer(0, 7);
    const std::vector<Solid>& solids = c.scene.solids;
    const char* name = "free";
    int axis = 0;
    switch (kind) {
      case 0:  // stands flush on the floor
        name = "on-floor";
        hi.z() -= lo.z();
        lo.z() = 0;
        break;
      case 1:  // touches the source's plane from below, or crosses it
        name = window ? "against-wall" : "touching-source-plane";
        if (window) {
          lo.x() = -2;
        } else {
          hi.z() = kHeight + (chance(0.5) ? 0.0 : kStep);
          lo.z() = std::min(lo.z(), hi.z() - kStep);
        }
        break;
      case 2:  // shares a face (and so edges) with the previous box
        if (!solids.empty()) {
          name = "sharing-face";
          axis = integer(0, 2);
          lo = lastLo_;
          hi = lastHi_;
          lo[axis] = lastHi_[axis];
          hi[axis] = lo[axis] + lattice(1, 3);
        }
        break;
      case 3:  // an edge collinear with a source edge (seen along the source's plane)
        name = "collinear-with-source";
        lo.x() = corner[chance(0.5) ? 0 : 2].x();
        lo.y() = corner[chance(0.5) ? 0 : 2].y();
        break;
      case 4:  // zero thickness: an empty solid
        name = "zero-thickness";
        axis = integer(0, 2);
        hi[axis] = lo[axis];
        break;
      case 5:  // thin (a pane, a sheet): kThinBox unless asked otherwise
        name = "thin";
        axis = integer(0, 2);
        hi[axis] = lo[axis] + thin_;
        break;
      default:
        break;
    }
    lastLo_ = lo;
    lastHi_ = hi;
    c.scene.solids.push_back(
        Solid{fmt::format("box{}", solids.size()), ConvexPolyhedron::box(lo, hi), -1});
    c.description += fmt::format("; {} box [{}, {}, {}]..[{}, {}, {}]", name, lo.x(), lo.y(),
                                 lo.z(), hi.x(), hi.y(), hi.z());
  }

  void addPoint(DegenerateCase& c, const Vec3& p, const Vec3& n, const char* why) {
    c.points.push_back({p, n.normalized(), -1});
    c.description += fmt::format("; {} point ({}, {}, {}) n ({}, {}, {})", why, p.x(), p.y(), p.z(),
                                 n.x(), n.y(), n.z());
  }

  void addPoints(DegenerateCase& c, const Vec3 corner[4], bool window) {
    // On the floor, on a lattice half as coarse as the boxes' (feet of boxes, their edges).
    for (int i = 0; i < 3; ++i) {
      addPoint(c, {0.5 * lattice(-16, 12), 0.5 * lattice(-16, 12), 0}, Vec3::UnitZ(), "floor");
    }
    // On a shadow boundary: a source corner through a box corner onto the floor.
    for (int i = 0; i < 2 && !c.scene.solids.empty(); ++i) {
      const ConvexPolyhedron& shape = c.scene.solids[integer(0, c.scene.solids.size() - 1)].shape;
      if (shape.vertices().empty()) continue;
      const Vec3 s = corner[integer(0, 3)];
      const Vec3 b = shape.vertices()[integer(0, shape.vertices().size() - 1)];
      if (b.z() <= 0 || b.z() >= s.z()) continue;
      addPoint(c, s + (b - s) * (s.z() / (s.z() - b.z())), Vec3::UnitZ(), "shadow-boundary");
    }
    // The source seen edge-on: a point in its plane, facing along it.
    if (window) {
      addPoint(c, {-2, lattice(-8, 8), lattice(0, 8)}, Vec3(0, chance(0.5) ? 1 : -1, 0), "edge-on");
      addPoint(c, {lattice(-6, 6), lattice(-8, 8), 0}, Vec3::UnitZ(), "sill-level");
    } else {
      addPoint(c, {lattice(-8, 8), lattice(-8, 8), kHeight}, Vec3(1, 0, 0), "edge-on");
      addPoint(c, {lattice(-8, 8), lattice(-8, 8), lattice(0, 7)},
               Vec3(lattice(-4, 4), lattice(-4, 4), 1), "tilted");
    }
  }

  std::mt19937_64 random_;
  double thin_;
  Vec3 lastLo_ = Vec3::Zero(), lastHi_ = Vec3::Zero();  // the box added last
};

}  // namespace penumbra::bench
