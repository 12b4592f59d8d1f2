#include "grid/iso_bands.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace penumbra {
namespace {

// A crossing of `level` on the mesh edge (a, b), a < b: the bracket the refinement narrows.
struct Crossing {
  int a, b, level;
  double t = 0.5;              // position along a → b
  double lowT = 0, highT = 1;  // bracket, E − level changes sign between them
  double lowF = 0, highF = 0;
  bool atJump = false;
};

using CrossingKey = std::array<int, 3>;

}  // namespace

int bandOf(double value, std::span<const double> levels) {
  return static_cast<int>(std::upper_bound(levels.begin(), levels.end(), value) - levels.begin());
}

IsoBands isoBands(const TriangleMesh& mesh, std::span<const double> illuminance,
                  std::span<const double> levels, const SurfaceIlluminance& evaluate, int rounds,
                  double tolerance) {
  // Every (edge, level) a contour crosses, with its linear estimate.
  std::map<CrossingKey, Crossing> crossings;
  const auto crossingOf = [&](int a, int b, int level) -> Crossing& {
    if (a > b) std::swap(a, b);
    auto [it, inserted] = crossings.try_emplace(CrossingKey{a, b, level});
    if (inserted) {
      Crossing& c = it->second;
      c.a = a;
      c.b = b;
      c.level = level;
      c.lowF = illuminance[a] - levels[level];
      c.highF = illuminance[b] - levels[level];
      c.t = c.lowF / (c.lowF - c.highF);
    }
    return it->second;
  };
  for (const auto& tri : mesh.triangles)
    for (int e = 0; e < 3; ++e) {
      const int a = tri[e], b = tri[(e + 1) % 3];
      const int la = bandOf(illuminance[a], levels), lb = bandOf(illuminance[b], levels);
      for (int level = std::min(la, lb); level < std::max(la, lb); ++level) crossingOf(a, b, level);
    }

  // Regula falsi on every unsettled crossing at once: one evaluation of their points per round.
  std::vector<Crossing*> all;
  for (auto& [key, c] : crossings) all.push_back(&c);
  // A bracket this short (m) is rounding: a thousandth of the mesh's smallest edge.
  double shortest = INFINITY;
  for (const auto& tri : mesh.triangles)
    for (int e = 0; e < 3; ++e)
      shortest =
          std::min(shortest, (mesh.vertices[tri[(e + 1) % 3]] - mesh.vertices[tri[e]]).norm());
  const double jumpWidth = 1e-6 * shortest;
  const auto at = [&](const Crossing& c) {
    return mesh.vertices[c.a] + c.t * (mesh.vertices[c.b] - mesh.vertices[c.a]);
  };
  for (int round = 0; round < rounds && !all.empty(); ++round) {
    std::vector<Vec3> points;
    for (const Crossing* c : all) points.push_back(at(*c));
    const std::vector<double> e = evaluate(points);
    std::vector<Crossing*> unsettled;
    for (std::size_t i = 0; i < all.size(); ++i) {
      Crossing& c = *all[i];
      const double f = e[i] - levels[c.level];
      if (std::abs(f) <= tolerance * levels[c.level]) continue;
      // The bracket is down to rounding and E still differs from the level: E jumps here.
      if ((c.highT - c.lowT) * (mesh.vertices[c.b] - mesh.vertices[c.a]).norm() <= jumpWidth) {
        c.atJump = true;
        continue;
      }
      unsettled.push_back(&c);
      // Keep the sign change inside [lowT, highT]; the Illinois variant halves the stale end's
      // value so that one-sided convergence does not stall.
      if ((f < 0) == (c.lowF < 0)) {
        c.lowT = c.t;
        c.lowF = f;
        c.highF *= 0.5;
      } else {
        c.highT = c.t;
        c.highF = f;
        c.lowF *= 0.5;
      }
      c.t = c.lowT + (c.highT - c.lowT) * c.lowF / (c.lowF - c.highF);
    }
    all = std::move(unsettled);
  }
  // Still unsettled after every round: E changes there faster than the refinement follows it,
  // which near a solid's corner is the corner of its shadow, a jump of E (the office cabinet's
  // top corner against the wall: 40 rounds, E 0 on one side of the bracket). Drawn where the
  // last round put it, and flagged like a jump: it does not carry its level.
  for (Crossing* c : all) c->atJump = true;
  // Several levels crossing one edge stay in the order of their levels (a refinement that found
  // another crossing of a level where E is not monotone would fold the band polygons).
  for (auto it = crossings.begin(); it != crossings.end();) {
    auto end = it;
    while (end != crossings.end() && end->first[0] == it->first[0] && end->first[1] == it->first[1])
      ++end;
    const bool rising = illuminance[it->second.a] < illuminance[it->second.b];
    double bound = rising ? 0.0 : 1.0;
    for (auto k = it; k != end; ++k) {
      Crossing& c = k->second;
      c.t = rising ? std::max(c.t, bound) : std::min(c.t, bound);
      bound = c.t;
    }
    it = end;
  }

  IsoBands out;
  for (const auto& [key, c] : crossings) out.contourVertices.push_back({at(c), c.level, c.atJump});
  // Per triangle: walk the boundary once per band, keeping the vertices and crossings whose value
  // lies in the band (Sutherland-Hodgman against "value >= low" and "value < high" at once).
  for (const auto& tri : mesh.triangles) {
    int lowest = bandOf(illuminance[tri[0]], levels), highest = lowest;
    for (int k = 1; k < 3; ++k) {
      const int b = bandOf(illuminance[tri[k]], levels);
      lowest = std::min(lowest, b);
      highest = std::max(highest, b);
    }
    for (int band = lowest; band <= highest; ++band) {
      IsoBandPolygon polygon{band, {}};
      for (int e = 0; e < 3; ++e) {
        const int a = tri[e], b = tri[(e + 1) % 3];
        const int ba = bandOf(illuminance[a], levels), bb = bandOf(illuminance[b], levels);
        if (ba == band) polygon.vertices.push_back(mesh.vertices[a]);
        // Crossings from a towards b that bound this band: level band-1 (its low side) and level
        // band (its high side), in the order a → b meets them.
        if (ba == bb) continue;
        const int step = bb > ba ? 1 : -1;
        for (int level = ba + (step > 0 ? 0 : -1); level != bb + (step > 0 ? 0 : -1);
             level += step) {
          if (level == band - 1 || level == band) {
            polygon.vertices.push_back(at(crossingOf(a, b, level)));
          }
        }
      }
      if (polygon.vertices.size() >= 3) out.polygons.push_back(std::move(polygon));
    }
    // Contour segments: for each level crossed in this triangle, the two crossing points.
    for (int level = lowest; level < highest; ++level) {
      std::vector<Vec3> ends;
      for (int e = 0; e < 3; ++e) {
        const int a = tri[e], b = tri[(e + 1) % 3];
        const int ba = bandOf(illuminance[a], levels), bb = bandOf(illuminance[b], levels);
        if (std::min(ba, bb) <= level && level < std::max(ba, bb))
          ends.push_back(at(crossingOf(a, b, level)));
      }
      if (ends.size() == 2) out.contourSegments.push_back({ends[0], ends[1]});
    }
  }
  return out;
}

}  // namespace penumbra
