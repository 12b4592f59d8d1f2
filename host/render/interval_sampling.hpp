#pragma once
// Interval sampling along scanlines (Nishita §2.5): illuminance is computed
// exactly every k samples of a row and linearly interpolated between, except where that would
// cross a boundary. k = 1 computes every sample and is the reference for the others.
//
// The plan is made in rounds around the rounds of exact evaluation:
//   1. firstPass(): the interval ends, and every sample of an interval that crosses a face
//      boundary (its samples do not all show the same face);
//   2. secondPass(classes): an interval whose ends differ in some source's shadow class (lit /
//      penumbra / umbra; "receives nothing" counts as umbra) is computed whole. One whose ends
//      are both lit or in umbra for every source is interpolated. One with a source in penumbra
//      at its ends gets its midpoint computed: inside a penumbra E is smooth but not linear, and
//      a shadow edge can run through an interval whose ends are both in penumbra;
//   3. thirdPass(illuminance): such an interval is interpolated in two halves when its midpoint
//      lies within kPenumbraLinearity of the straight line between its ends, and computed whole
//      otherwise.
// Only samples that need illuminance take part (`needed`: samples that show a solid's face).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "shadow/shadow_class.hpp"

namespace penumbra {

class IntervalPlan {
 public:
  // How far (relative to the largest E of the interval) a penumbra interval's midpoint may be
  // off the line between its ends for the interval to be interpolated: 1 %, a tenth of what a
  // lux meter's class-A tolerance allows, and invisible in a rendered image.
  static constexpr double kPenumbraLinearity = 0.01;

  // `faceIds` row-major, width × height; `needed` marks the samples that need E.
  IntervalPlan(int width, int height, std::span<const uint32_t> faceIds,
               std::span<const uint8_t> needed, int interval);

  // Samples to compute exactly first, in row-major order.
  const std::vector<std::size_t>& firstPass() const { return first_; }
  // `classes[sample * sources + s]`, valid at every sample computed so far.
  std::vector<std::size_t> secondPass(std::span<const ShadowClass> classes, int sources);
  // `illuminance` valid at every sample computed so far.
  std::vector<std::size_t> thirdPass(std::span<const float> illuminance);
  // Fills every interpolated sample between its interval's ends, `channels` values per sample
  // in `values` (exact samples already filled).
  void interpolate(std::span<float> values, int channels) const;

 private:
  struct Interval {
    std::size_t a, b;  // exact ends; a < b, same row
  };
  static void appendInterior(const Interval& interval, std::vector<std::size_t>& out);
  std::vector<std::size_t> first_;
  std::vector<Interval> undecided_;     // one face throughout: after the first pass
  std::vector<Interval> checking_;      // penumbra intervals whose midpoint is computed
  std::vector<Interval> interpolated_;  // decided
};

}  // namespace penumbra
