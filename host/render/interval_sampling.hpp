#pragma once
// Interval sampling along scanlines (Nishita §2.5, DESIGN.md step 6): illuminance is computed
// exactly every k samples of a row and linearly interpolated between, except where that would
// cross a boundary: an interval whose samples do not all show the same face is computed whole,
// and so is one whose two ends differ in some source's shadow class (lit / penumbra / umbra).
// k = 1 computes every sample and is the reference for the others.
//
// The plan is made in two passes around the two rounds of exact evaluation:
//   1. firstPass(): interval ends, and every sample of intervals that cross a face boundary;
//   2. once their shadow classes are known, secondPass(): the inner samples of intervals whose
//      ends differ in class; every other inner sample is interpolated (interpolate()).
// Only samples that need illuminance take part (`needed`: samples showing a solid's face).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace penumbra {

class IntervalPlan {
 public:
  // `faceIds` row-major, width × height; `needed` marks the samples that need E.
  IntervalPlan(int width, int height, std::span<const uint32_t> faceIds,
               std::span<const uint8_t> needed, int interval);

  // Samples to compute exactly first, in row-major order.
  const std::vector<std::size_t>& firstPass() const { return first_; }
  // Inner samples of the undecided intervals whose ends `sameClasses(a, b)` says differ.
  std::vector<std::size_t> secondPass(
      const std::function<bool(std::size_t a, std::size_t b)>& sameClasses);
  // Fills every remaining inner sample by linear interpolation between its interval's ends,
  // `channels` values per sample in `values` (exact samples already filled).
  void interpolate(std::span<float> values, int channels) const;

 private:
  struct Interval {
    std::size_t a, b;  // exact ends; a < b, same row, b − a ≥ 2
  };
  std::vector<std::size_t> first_;
  std::vector<Interval> undecided_;     // uniform intervals, before secondPass
  std::vector<Interval> interpolated_;  // after secondPass
};

}  // namespace penumbra
