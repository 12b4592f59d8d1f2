#pragma once
// The stress suite's checks (docs/reliability.md), shared by bench/degenerate_stress.cpp (10^4
// configurations) and tests/degenerate_test.cpp (a few hundred). At every point of every
// configuration the kernel's E must be finite, ≥ 0, not above the unoccluded E, and within the
// occlusion criterion of the independent reference (tests/occlusion_test.cpp: 2e-3 of the
// unoccluded E, reference n ≥ 1024). Float kernels carry an absolute floor of
// Tolerance::kKernelRelative × π·L (π·L is the most a source of luminance L can give), which is
// what "zero" means for a point that sees the source edge-on.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "bench/degenerate_scenes.hpp"
#include "engine/illuminance_engine.hpp"
#include "geometry/tolerance.hpp"
#include "reference/reference_illuminance.hpp"

namespace penumbra::bench {

inline constexpr double kStressReferenceTolerance = 2e-3;  // of the unoccluded E
inline constexpr int kStressReferenceN = 1024;

struct StressFigures {
  long configurations = 0, points = 0;
  long insideSolids = 0;  // points strictly inside a solid: skipped, as the grid layer does
  long nonFinite = 0, negative = 0, aboveUnoccluded = 0, beyondReference = 0;
  double worstRelative =
      0.0;                // max |E − E_ref| / E_unoccluded where E_unoccluded is above the floor
  std::string worstCase;  // its configuration and point
  std::vector<std::string> failures;  // one line per failed point (the first 20)

  long failed() const { return nonFinite + negative + aboveUnoccluded + beyondReference; }
};

// Evaluates one configuration with `engine` (its scene is replaced) and `open` (the same without
// occluders) and adds to `figures`.
inline void checkDegenerateCase(const DegenerateCase& c, IlluminanceEngine& engine,
                                IlluminanceEngine& open, int referenceN, StressFigures& figures) {
  Scene unoccluded = c.scene;
  unoccluded.solids.clear();
  engine.setScene(c.scene);
  open.setScene(unoccluded);
  const std::vector<double> e = engine.illuminance(c.points);
  const std::vector<double> u = open.illuminance(c.points);
  const std::vector<double> ref = referenceIlluminance(c.scene, c.points, referenceN);
  double luminance = 0.0;
  for (const Source& s : c.scene.sources) luminance += s.luminance;
  const double floor = Tolerance::kKernelRelative * std::numbers::pi * luminance;
  // The grid layer never asks the kernel about a point strictly inside a solid (gridSamples marks
  // it and writes E = 0; the kernel, told nothing, would see through the solid): skip such
  // points with the same test and tolerance.
  const double inputTolerance = Tolerance::kRelativeInput * std::max(c.scene.size(), 1.0);
  ++figures.configurations;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    bool inside = false;
    for (const Solid& solid : c.scene.solids)
      inside = inside || solid.shape.containsStrictly(c.points[i].position, inputTolerance);
    if (inside) {
      ++figures.insideSolids;
      continue;
    }
    ++figures.points;
    std::string fault;
    if (!std::isfinite(e[i])) {
      ++figures.nonFinite;
      fault = "not finite";
    } else if (e[i] < 0.0) {
      ++figures.negative;
      fault = "negative";
    } else if (e[i] > u[i] * (1.0 + Tolerance::kKernelRelative) + floor) {
      ++figures.aboveUnoccluded;
      fault = "above the unoccluded E";
    } else if (std::abs(e[i] - ref[i]) > kStressReferenceTolerance * u[i] + floor) {
      ++figures.beyondReference;
      fault = "off the reference";
    }
    const std::string where =
        fmt::format("point {} of [{}]: E {} lx, reference {} lx, unoccluded {} lx", i,
                    c.description, e[i], ref[i], u[i]);
    if (!fault.empty() && figures.failures.size() < 20) {
      figures.failures.push_back(fault + ": " + where);
    }
    if (u[i] > floor && std::isfinite(e[i])) {
      const double relative = std::abs(e[i] - ref[i]) / u[i];
      if (relative > figures.worstRelative) {
        figures.worstRelative = relative;
        figures.worstCase = where;
      }
    }
  }
}

}  // namespace penumbra::bench
