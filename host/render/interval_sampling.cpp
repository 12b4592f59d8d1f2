#include "render/interval_sampling.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace penumbra {

struct IntervalPlan::Context {
  std::span<const ShadowClass> classes;
  std::span<const ShadowEdges> edges;
  std::span<const SampleValues> checked;

  std::size_t columns() const { return edges.size(); }
  // Whether the classes at i and j are the same in every column whose edges are `from` or
  // harder (ShadowEdges' order).
  bool sameClasses(std::size_t i, std::size_t j, ShadowEdges from = ShadowEdges::Soft) const {
    for (std::size_t c = 0; c < columns(); ++c)
      if (edges[c] >= from && classes[i * columns() + c] != classes[j * columns() + c])
        return false;
    return true;
  }
  // Whether a source whose edges are `from` or harder is in penumbra at i.
  bool inPenumbra(std::size_t i, ShadowEdges from = ShadowEdges::Soft) const {
    for (std::size_t c = 0; c < columns(); ++c)
      if (edges[c] >= from && classes[i * columns() + c] == ShadowClass::Penumbra) return true;
    return false;
  }

  // Whether the value at `m`, a share t of the way from `a` to `b`, lies within `tolerance` of
  // the line between them (relative to the largest of the three), in every channel.
  bool onLine(std::size_t a, std::size_t m, std::size_t b, double t, double tolerance) const {
    for (const SampleValues& set : checked)
      for (int c = 0; c < set.channels; ++c) {
        const double va = set.values[a * set.channels + c], vb = set.values[b * set.channels + c],
                     vm = set.values[m * set.channels + c];
        const double scale = std::max({std::abs(va), std::abs(vb), std::abs(vm)});
        if (std::abs(vm - (va + t * (vb - va))) > tolerance * scale) return false;
      }
    return true;
  }
  // Whether the second difference through p, q, r (equally spaced) predicts a linear
  // interpolation error |Δ²|/8 of at most kInterpolationError of the values, in every channel.
  bool gentlyCurved(std::size_t p, std::size_t q, std::size_t r) const {
    for (const SampleValues& set : checked)
      for (int c = 0; c < set.channels; ++c) {
        const double vp = set.values[p * set.channels + c], vq = set.values[q * set.channels + c],
                     vr = set.values[r * set.channels + c];
        const double scale = std::max({std::abs(vp), std::abs(vq), std::abs(vr)});
        const double predicted = std::abs(vp - 2 * vq + vr) / (set.kinks ? 2 : 8);
        if (predicted > kInterpolationError * scale) return false;
      }
    return true;
  }
};

IntervalPlan::IntervalPlan(int width, int height, std::span<const uint32_t> faceIds,
                           std::span<const uint8_t> needed, int interval)
    : width_(width), faceIds_(faceIds), known_(static_cast<std::size_t>(width) * height, 0) {
  const int k = std::max(interval, 1);
  // (a) in the other direction: a sample whose neighbour above or below shows another face (or
  // none) is exact, and cuts its interval there. The light changes fastest where surfaces meet
  // (contact shadows at a desk's foot, a wall's corner), and a row's interval cannot see it.
  const auto besideAnEdge = [&](int x, int y) {
    const std::size_t i = static_cast<std::size_t>(y) * width + x;
    return (y > 0 && faceIds[i - width] != faceIds[i]) ||
           (y + 1 < height && faceIds[i + width] != faceIds[i]);
  };
  for (int y = 0; y < height; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * width;
    for (int a = 0; a < width; a += k) {
      const int b = std::min(a + k, width - 1);
      if (needed[row + a]) first_.push_back(row + a);
      if (b <= a) break;  // the last sample of the row was this interval's start
      // (a) Interpolation needs both ends on the same face and nothing else in between.
      bool uniform = needed[row + a] != 0;
      for (int x = a + 1; x <= b && uniform; ++x) uniform = faceIds[row + x] == faceIds[row + a];
      if (uniform) {
        int start = a;
        for (int x = a + 1; x <= b; ++x) {
          if (x < b && !besideAnEdge(x, y)) continue;
          if (x < b) first_.push_back(row + x);
          if (x - start >= 2) ends_.push_back(Interval{row + start, row + x});
          start = x;
        }
      } else {
        for (int x = a + 1; x < b; ++x)
          if (needed[row + x]) first_.push_back(row + x);
      }
      if (b == width - 1) {
        if (needed[row + b]) first_.push_back(row + b);
        break;
      }
    }
  }
  requested_ = first_;
}

void IntervalPlan::request(std::size_t sample, Decisions& d) const {
  if (known_[sample] == 0) d.out.push_back(sample);  // marked requested once the round is decided
}

void IntervalPlan::requestInterior(const Interval& interval, Decisions& d) const {
  for (std::size_t i = interval.a + 1; i < interval.b; ++i) request(i, d);
}

void IntervalPlan::decideEnds(const Interval& interval, const Context& c, Decisions& d) const {
  if (interval.b - interval.a < 2) return;  // nothing between
  if (c.inPenumbra(interval.a, ShadowEdges::Stepped) ||
      c.inPenumbra(interval.b, ShadowEdges::Stepped)) {
    requestInterior(interval, d);  // (b): a staircase of hard shadows
  } else if (!c.sameClasses(interval.a, interval.b)) {
    // (b): a shadow edge lies between the ends. The midpoint says in which half; each half is
    // then decided on its own, down to where the edge's interval is computed whole. Where a
    // sharp source's class changes, the interval is computed whole: a half with the same class
    // at both ends can still hide an edge of its hard shadows (the sun's penumbra class holds
    // the shadows inside its beam).
    if (interval.b - interval.a >= 3 && c.sameClasses(interval.a, interval.b, ShadowEdges::Sharp)) {
      request((interval.a + interval.b) / 2, d);
      d.midpoints.push_back(interval);
    } else {
      requestInterior(interval, d);
    }
  } else if (interval.b - interval.a >= 3) {
    // Gentle curvature through the neighbouring intervals' ends on both sides (same face, same
    // classes): (e) at the interval's own length stands for (c). In a penumbra too: a shadow
    // edge of another occluder inside the interval bends the light there, and the second
    // differences on the side it lies on straddle it. Not in a sharp source's penumbra (the
    // sun's), which can hide a sliver of light between the ends.
    const Curvature around = curvature(interval, c);
    if (!c.inPenumbra(interval.a, ShadowEdges::Sharp) && around.sides == 2 && around.gentle) {
      fill(interval, c.checked);
      return;
    }
    request((interval.a + interval.b) / 2, d);  // (c)
    d.midpoints.push_back(interval);
  } else if (c.inPenumbra(interval.a)) {
    // A single inner sample in a penumbra: checking it costs as much as computing it.
    requestInterior(interval, d);
  } else {
    d.halves.push_back(interval);  // a single inner sample, lit or in umbra: (e) decides
  }
}

void IntervalPlan::decideMidpoint(const Interval& interval, const Context& c, Decisions& d) const {
  const std::size_t m = (interval.a + interval.b) / 2;
  const double t = static_cast<double>(m - interval.a) / (interval.b - interval.a);
  if (!c.sameClasses(interval.a, m) || !c.sameClasses(m, interval.b) ||
      !c.onLine(interval.a, m, interval.b, t, kMidpointMiss)) {
    // Each half is an interval of its own, its ends known: (b), (c) and (e) again, so that a
    // long interval costs no more than two short ones where the light bends.
    d.ends.push_back(Interval{interval.a, m});
    d.ends.push_back(Interval{m, interval.b});
    return;
  }
  for (const Interval half : {Interval{interval.a, m}, Interval{m, interval.b}}) {
    if (half.b - half.a < 2) continue;  // no sample between
    if (c.inPenumbra(half.a) && half.b - half.a >= 3) {
      request((half.a + half.b) / 2, d);  // (d)
      d.midpoints.push_back(half);
    } else {
      d.halves.push_back(half);
    }
  }
}

IntervalPlan::Curvature IntervalPlan::curvature(const Interval& interval, const Context& c) const {
  // The exact samples one length beyond each end, where they show the same face in the same
  // classes (an edge or shadow boundary there says nothing about the curvature here).
  const std::size_t length = interval.b - interval.a;
  const std::size_t rowStart = interval.a - interval.a % width_;
  const auto usable = [&](std::size_t neighbour, std::size_t end) {
    return known_[neighbour] == 1 && faceIds_[neighbour] == faceIds_[end] &&
           c.sameClasses(neighbour, end);
  };
  Curvature result;
  if (interval.a >= rowStart + length && usable(interval.a - length, interval.a)) {
    ++result.sides;
    result.gentle &= c.gentlyCurved(interval.a - length, interval.a, interval.b);
  }
  const std::size_t beyond = interval.b + length;
  if (beyond < rowStart + width_ && usable(beyond, interval.b)) {
    ++result.sides;
    result.gentle &= c.gentlyCurved(interval.a, interval.b, beyond);
  }
  return result;
}

void IntervalPlan::decideHalf(const Interval& half, const Context& c, Decisions& d) const {
  // (e), on evidence: the second differences on one side at least, where neither end has
  // another face or class beyond it; on both sides in a penumbra, an S (the share of a disk or a
  // polygon seen past an edge) whose second differences vanish at its inflection, where a
  // midpoint lies on the line between the ends, so that the side towards the penumbra's edge is
  // seen too.
  const Curvature around = curvature(half, c);
  const bool inPenumbra = c.inPenumbra(half.a) || c.inPenumbra(half.b);
  if (around.gentle && around.sides >= (inPenumbra ? 2 : 1)) {
    fill(half, c.checked);
  } else if (half.b - half.a >= 3) {
    d.ends.push_back(half);  // (c) again, as an interval of its own
  } else {
    requestInterior(half, d);
  }
}

std::vector<std::size_t> IntervalPlan::next(std::span<const ShadowClass> classes,
                                            std::span<const ShadowEdges> edges,
                                            std::span<const SampleValues> checked) {
  for (std::size_t i : requested_) known_[i] = 1;
  requested_.clear();
  const Context c{classes, edges, checked};
  std::vector<std::size_t> out;
  // The halves of the last call first: every sample it asked for is known now, so (e) sees the
  // most neighbours. Then the midpoints it asked for, then the ends of the first pass. Each
  // interval's decision reads only what is known (known_ == 1), asks only for samples inside it
  // and fills only its inside when it is interpolated, and the intervals do not overlap, so they
  // are decided in parallel and neither the plan nor the values depend on their order.
  while (out.empty() && !(halves_.empty() && midpoints_.empty() && ends_.empty())) {
    std::vector<Interval> halves = std::move(halves_), midpoints = std::move(midpoints_),
                          ends = std::move(ends_);
    halves_.clear();
    midpoints_.clear();
    ends_.clear();
    tbb::enumerable_thread_specific<Decisions> decided;
    const auto decideAll = [&](const std::vector<Interval>& list, auto decide) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, list.size(), kIntervalsPerTask),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          Decisions& d = decided.local();
                          for (std::size_t j = range.begin(); j != range.end(); ++j)
                            (this->*decide)(list[j], c, d);
                        });
    };
    decideAll(halves, &IntervalPlan::decideHalf);
    decideAll(midpoints, &IntervalPlan::decideMidpoint);
    decideAll(ends, &IntervalPlan::decideEnds);
    for (Decisions& d : decided) {
      out.insert(out.end(), d.out.begin(), d.out.end());
      ends_.insert(ends_.end(), d.ends.begin(), d.ends.end());
      midpoints_.insert(midpoints_.end(), d.midpoints.begin(), d.midpoints.end());
      halves_.insert(halves_.end(), d.halves.begin(), d.halves.end());
    }
    // Halves found now wait for the next call unless nothing else is asked for: then they are
    // decided at once, with what is known.
  }
  for (std::size_t i : out) known_[i] = 2;  // requested: known once its round is computed
  std::sort(out.begin(), out.end());
  requested_ = out;
  return out;
}

void IntervalPlan::fill(const Interval& interval, std::span<const SampleValues> sets) {
  // In float, stepping from the start: a few roundings of the values, far below the 0.1 % the
  // plan allows an interpolated value.
  const std::size_t steps = interval.b - interval.a;
  const float length = static_cast<float>(steps);
  for (const SampleValues& set : sets) {
    const int channels = set.channels;
    float* const a = &set.values[interval.a * channels];
    const float* const b = &set.values[interval.b * channels];
    for (int c = 0; c < channels; ++c) {
      const float step = (b[c] - a[c]) / length;
      for (std::size_t i = 1; i < steps; ++i)
        a[i * channels + c] = a[c] + static_cast<float>(i) * step;
    }
  }
}

}  // namespace penumbra
