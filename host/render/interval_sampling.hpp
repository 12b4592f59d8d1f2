#pragma once
// Interval sampling along scanlines (Nishita §2.5): illuminance is computed exactly every k
// samples of a row and interpolated linearly between where the plan finds the light smooth
// enough. k = 1 computes every sample and is the reference for the others.
//
// What decides where a sample is exact (docs/render.md says it with the measured errors):
//   (a) face edges: an interval whose samples do not all show the same face is computed whole;
//   (b) shadow classes: an interval whose ends differ in some source's or luminaire's shadow
//       class (lit / penumbra / umbra; "receives nothing" counts as umbra) has a shadow edge
//       between them: one of 3 or more steps gets its midpoint computed and each half is decided
//       as an interval of its own, so the edge is bracketed down to an interval of 2 steps,
//       which is computed whole; where a sharp or stepped source's class differs, and wherever
//       a stepped source is in penumbra at an end, the interval is computed whole;
//   (c) the midpoint: an interval of 3 or more steps gets its midpoint computed, unless (e) at
//       its own length passes on both sides and no sharp or stepped source (ShadowEdges) is in
//       penumbra at its ends (then it is interpolated whole); one of 2 steps goes
//       to (e) directly, or is computed when a source is in penumbra. If the midpoint's classes
//       differ from an end's, or the straight line between the ends misses any of its values by
//       more than kMidpointMiss of that value, the two halves are decided as intervals of their
//       own ((b), (c), (e): a long interval costs no more than two short ones where the light
//       bends), otherwise the halves go on to (d), (e);
//   (d) penumbra halves: a half with a source in penumbra at its ends (where E is smooth but not
//       quadratic, and a shadow edge may run between two penumbra samples) of 3 or more steps
//       gets its own midpoint, and (c) again;
//   (e) neighbour second differences: a half is interpolated only if the second differences
//       through its ends and the exact samples one half-length beyond them (same face, same
//       classes) predict an interpolation error of at most kInterpolationError, on one side at
//       least (with no side usable there is no evidence), on both where a source is in
//       penumbra at an end (a penumbra is an S, whose second differences vanish at its
//       inflection); otherwise a half of 3 or more steps is decided as an interval of its own
//       ((b), (c)), one of 2 computed.
// The bound behind (c) and (e): for a quadratic the line between the ends misses the midpoint by
// h²|E''|/8 over a length h, so a half misses by a quarter of what the whole missed at its
// midpoint; kMidpointMiss = 4 · kInterpolationError, and (e) estimates the same h²|E''|/8 from
// |second difference| / 8, at either end, so that curvature that changes along the row counts.
// Values that may bend at a point (SampleValues::kinks: the interreflected light, from a field of
// quadratic triangles) are asked four times as much: a kink halfway misses by |Δ²|/2.
// Only samples that need illuminance take part (`needed`: samples that show a solid's face).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "shadow/shadow_class.hpp"

namespace penumbra {

// What a source's shadow class says of its light between two samples (rules (b) and (c)),
// ordered by how much less of it may be interpolated.
enum class ShadowEdges : uint8_t {
  Soft,     // an area source's: its light is smooth across its penumbra
  Sharp,    // the sun's: its penumbra class also holds the shadows inside its beam, where a
            // sliver of sun can lie between two samples of that class
  Stepped,  // a subdivided luminaire's: in its penumbra (some cells hidden) the light is a
            // staircase of the cells' hard shadows, which no line between samples follows
};

// Values per sample that the plan checks and fills (E in lx, the RGB luminance), `channels` per
// sample.
struct SampleValues {
  std::span<float> values;
  int channels = 1;
  // Whether the values may bend sharply at a point between samples, not only curve (the
  // interreflected light from a field of quadratic triangles, whose slope changes across their
  // edges): a kink halfway along an interval misses the line by 4 times what the second
  // differences through its ends predict for a quadratic, so (e) asks 4 times as much of them.
  bool kinks = false;
};

class IntervalPlan {
 public:
  // The largest interpolation error a half may have, relative to its own value (each channel):
  // 0.1 %, a tenth of the 1 % a pixel may differ from the exact render and below what a display
  // shows (one 8-bit step is 0.4 % or more).
  static constexpr double kInterpolationError = 0.001;
  // How far the straight line between an interval's ends may miss its midpoint: four times the
  // above, because each half then misses by a quarter of it (for a quadratic).
  static constexpr double kMidpointMiss = 4 * kInterpolationError;

  // `faceIds` row-major, width × height, kept by reference: they must outlive the plan;
  // `needed` marks the samples that need E.
  IntervalPlan(int width, int height, std::span<const uint32_t> faceIds,
               std::span<const uint8_t> needed, int interval);

  // Samples to compute exactly first, in row-major order: every interval's ends, and every
  // sample of an interval across a face edge.
  const std::vector<std::size_t>& firstPass() const { return first_; }
  // The next samples to compute, given the shadow classes (`classes[sample * columns + c]`)
  // and the checked values at every sample computed so far; empty once every interval is
  // decided. Each interval it decides to interpolate is filled at once, in every set of
  // `checked`, from its exact ends: once next() returns empty, every sample that needs E holds
  // its value. `edges` has one entry per class column.
  std::vector<std::size_t> next(std::span<const ShadowClass> classes,
                                std::span<const ShadowEdges> edges,
                                std::span<const SampleValues> checked);

 private:
  struct Interval {
    std::size_t a, b;  // exact ends; a < b, same row
  };
  struct Context;  // what one call of next() reads
  // What deciding some intervals gives: samples to compute, and intervals for each list.
  struct Decisions {
    std::vector<std::size_t> out;  // samples to compute
    std::vector<Interval> ends, midpoints, halves;
  };
  static constexpr std::size_t kIntervalsPerTask = 8192;

  // Sets the samples inside `interval` on the straight line between its ends: a decision to
  // interpolate fills at once, while the ends it has just read are in cache.
  static void fill(const Interval& interval, std::span<const SampleValues> sets);
  void requestInterior(const Interval& interval, Decisions& d) const;
  void request(std::size_t sample, Decisions& d) const;
  void decideEnds(const Interval& interval, const Context& c, Decisions& d) const;
  void decideMidpoint(const Interval& interval, const Context& c, Decisions& d) const;
  void decideHalf(const Interval& half, const Context& c, Decisions& d) const;
  // (e): how many of the two neighbours one length beyond the ends could be used, and whether
  // the second differences through them are gentle.
  struct Curvature {
    int sides = 0;
    bool gentle = true;
  };
  Curvature curvature(const Interval& interval, const Context& c) const;

  int width_ = 0;
  std::span<const uint32_t> faceIds_;  // the caller's, which outlive the plan
  std::vector<uint8_t> known_;         // 1: computed exactly, values given to the last next()
  std::vector<std::size_t> first_;
  std::vector<std::size_t> requested_;  // returned by the last next(): known at the next call
  std::vector<Interval> ends_;          // one face throughout, ends computed (also failed halves)
  std::vector<Interval> midpoints_;     // midpoint requested
  std::vector<Interval> halves_;        // passed (c) or (d), waiting for (e)
};

}  // namespace penumbra
