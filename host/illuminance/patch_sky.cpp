#include "illuminance/patch_sky.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "illuminance/far_polygon.hpp"

namespace penumbra {
namespace {

constexpr std::array<int, 7> kTregenzaBandPatches = {30, 30, 24, 24, 18, 12, 6};

// Azimuths are kept as fractions of the full turn, so that the corners two rows share compare
// equal (a shared corner of rows of n and n' patches is j/n = j'/n').
constexpr double kSameAzimuth = 1e-12;

Vec3 skyDirection(double altitude, double turn) {
  const double phi = 2.0 * std::numbers::pi * turn;
  return Vec3(std::cos(altitude) * std::cos(phi), std::cos(altitude) * std::sin(phi),
              std::sin(altitude));
}

// One ring: its altitude and its corners' azimuths (turns, sorted, in [0, 1)).
struct SkyRing {
  double altitude = 0.0;
  std::vector<double> turns;

  // The direction on the ring's polygon at azimuth `turn`: a corner, or the point where the
  // meridian plane at that azimuth meets the arc between the corners around it.
  Vec3 at(double turn) const {
    const auto above = std::lower_bound(turns.begin(), turns.end(), turn - kSameAzimuth);
    if (above != turns.end() && std::abs(*above - turn) <= kSameAzimuth)
      return skyDirection(altitude, *above);
    const double hi = above == turns.end() ? turns.front() + 1.0 : *above;
    const double lo = above == turns.begin() ? turns.back() - 1.0 : *(above - 1);
    const Vec3 a = skyDirection(altitude, lo), b = skyDirection(altitude, hi);
    const double phi = 2.0 * std::numbers::pi * turn;
    const Vec3 meridianNormal(-std::sin(phi), std::cos(phi), 0.0);
    const double t = -meridianNormal.dot(a) / meridianNormal.dot(b - a);
    return (a + t * (b - a)).normalized();
  }
};

std::vector<double> rowTurns(int patches) {
  std::vector<double> turns;
  for (int j = 0; j < patches; ++j) turns.push_back(static_cast<double>(j) / patches);
  return turns;
}

std::vector<double> mergedTurns(std::vector<double> a, const std::vector<double>& b) {
  a.insert(a.end(), b.begin(), b.end());
  std::sort(a.begin(), a.end());
  a.erase(std::unique(a.begin(), a.end(),
                      [](double x, double y) { return std::abs(x - y) <= kSameAzimuth; }),
          a.end());
  return a;
}

// The corners' turns of `ring` strictly inside (lo, hi).
void addInside(const SkyRing& ring, double lo, double hi, std::vector<double>& out) {
  for (double t : ring.turns)
    if (t > lo + kSameAzimuth && t < hi - kSameAzimuth) out.push_back(t);
}

Vec3 meanDirection(const std::vector<Vec3>& corners) {
  Vec3 sum = Vec3::Zero();
  for (const Vec3& c : corners) sum += c;
  return sum.normalized();
}

}  // namespace

SkySubdivision skySubdivision(int subdivision) {
  if (subdivision < 1)
    throw std::invalid_argument("sky subdivision " + std::to_string(subdivision) +
                                ": must be at least 1");
  const int m = subdivision;
  const int rows = 7 * m;
  const double step = 0.5 * std::numbers::pi / (7.0 * m + 0.5);
  std::vector<int> patches;
  for (int r = 0; r < rows; ++r) patches.push_back(kTregenzaBandPatches[r / m] * m);
  // Ring k separates rows k − 1 and k; ring `rows` is the cap's edge.
  std::vector<SkyRing> rings(static_cast<std::size_t>(rows) + 1);
  for (int k = 0; k <= rows; ++k) {
    SkyRing& ring = rings[static_cast<std::size_t>(k)];
    ring.altitude = k * step;
    if (k > 0) ring.turns = rowTurns(patches[k - 1]);
    if (k < rows) ring.turns = mergedTurns(ring.turns, rowTurns(patches[k]));
  }
  SkySubdivision division;
  division.subdivision = m;
  for (int r = 0; r < rows; ++r) {
    const SkyRing& lower = rings[static_cast<std::size_t>(r)];
    const SkyRing& upper = rings[static_cast<std::size_t>(r) + 1];
    const int n = patches[r];
    for (int j = 0; j < n; ++j) {
      const int patch = static_cast<int>(division.patchCentres.size());
      const double lo = static_cast<double>(j) / n, hi = static_cast<double>(j + 1) / n;
      division.patchCentres.push_back(skyDirection((r + 0.5) * step, 0.5 * (lo + hi)));
      std::vector<double> inside;
      addInside(lower, lo, hi, inside);
      addInside(upper, lo, hi, inside);
      const std::vector<double> cuts =
          mergedTurns({lo, hi}, inside);  // a corner of both rings once
      for (std::size_t s = 0; s + 1 < cuts.size(); ++s) {
        const double a = cuts[s], b = cuts[s + 1];
        const double bWrapped = b >= 1.0 - kSameAzimuth ? 0.0 : b;
        SkyPiece piece;
        piece.corners = {lower.at(a), lower.at(bWrapped), upper.at(bWrapped), upper.at(a)};
        piece.centre = meanDirection(piece.corners);
        piece.patch = patch;
        division.pieces.push_back(std::move(piece));
      }
    }
  }
  // The cap: the polygon of the last ring's corners.
  const SkyRing& edge = rings.back();
  SkyPiece cap;
  for (double t : edge.turns) cap.corners.push_back(skyDirection(edge.altitude, t));
  cap.centre = Vec3::UnitZ();
  cap.patch = static_cast<int>(division.patchCentres.size());
  division.patchCentres.push_back(Vec3::UnitZ());
  division.pieces.push_back(std::move(cap));
  return division;
}

ConvexPolygon piecePolygon(const SkyPiece& piece, const Vec3& point, double distance) {
  std::vector<Vec3> vertices;
  vertices.reserve(piece.corners.size());
  for (const Vec3& c : piece.corners)
    vertices.push_back(point + (distance / c.dot(piece.centre)) * c);
  ConvexPolygon polygon(std::move(vertices));
  return polygon.normal().dot(piece.centre) > 0.0 ? polygon.reversed() : polygon;
}

PatchSky patchSky(int subdivision, const std::function<double(const Vec3&)>& luminance) {
  PatchSky sky{skySubdivision(subdivision), {}};
  for (const Vec3& centre : sky.division.patchCentres) sky.luminance.push_back(luminance(centre));
  return sky;
}

double horizontalIlluminance(const PatchSky& sky) {
  const Scene empty;
  const SamplePoint up{Vec3::Zero(), Vec3::UnitZ(), -1};
  double e = 0.0;
  for (const SkyPiece& piece : sky.division.pieces)
    e += sky.luminance[static_cast<std::size_t>(piece.patch)] *
         visibleProjectedSolidAngle(piecePolygon(piece, up.position, 1.0), up, empty, 0.0);
  return e;
}

}  // namespace penumbra
