#pragma once
// Where a view's interreflected light is gathered exactly, and how the other samples get it.
// The sample grid is cut into square cells of `spacing` samples. A cell whose samples do not all
// show the same face of a solid is cut in four, down to single samples, which are gathered; so
// every sample next to a face edge is gathered and a value is never interpolated across a face
// edge or from a source or the sky. A cell on one face is gathered at its four corners, its
// centre and the midpoints of its edges: if these five lie within kTolerance of the bilinear
// interpolation of the corners (relative to their own total E) the cell is interpolated
// bilinearly, otherwise it is cut in four at those points and each quarter checked in the same
// way. The interreflected light has no hard
// shadows (every element is a broad source) but it does bend steeply into concave corners and
// under furniture: the check puts the gathered samples there. The direct light keeps its own
// exact plan (interval_sampling.hpp).
//
// The plan is made in rounds around the rounds of gathering: exact() first, then
// next(indirect, direct) until it returns nothing, then interpolate().
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace penumbra {

class LatticePlan {
 public:
  // How far a cell's centre and edge midpoints may lie from the bilinear interpolation of its
  // corners, relative to their total E, for the cell to be interpolated: below the mesh's own
  // accuracy on the total E (1.8e-3 with the default elements, docs/method.md), so that the
  // interpolation adds less than the mesh's error where the five points stand for the cell,
  // and above the gather's own float scatter from pixel to pixel (about 1e-4 of E), which a
  // tighter test would chase down to single pixels.
  static constexpr double kTolerance = 1e-3;

  // `faceIds` row-major, width × height; `needed` marks the samples that show a solid's face.
  // Throws std::invalid_argument for a spacing below 1; spacing 1 gathers every sample.
  LatticePlan(int width, int height, std::span<const uint32_t> faceIds,
              std::span<const uint8_t> needed, int spacing);

  // Samples to gather first, in row-major order.
  const std::vector<std::size_t>& exact() const { return first_; }
  // The next samples to gather, from the values gathered so far: `indirect` 3 channels per
  // sample (lx), `direct` the direct E per sample (lx). Empty when the plan is complete.
  std::vector<std::size_t> next(std::span<const float> indirect, std::span<const float> direct);
  // Every needed sample that is not gathered, filled from the gathered ones, `channels` values
  // per sample in `values`.
  void interpolate(std::span<float> values, int channels) const;
  // Samples gathered in all rounds so far.
  std::size_t gathered() const { return gathered_; }

 private:
  struct Cell {
    int x0, x1, y0, y1;
  };
  // Splits by faces, marking corners and centres of one-face cells to gather into `out`.
  void split(const Cell& cell, std::vector<std::size_t>& out);
  // A one-face cell: gather its corners, centre and edge midpoints (all of it when small).
  void check(const Cell& cell, std::vector<std::size_t>& out);
  void quarter(const Cell& cell, bool byFace, std::vector<std::size_t>& out);
  bool oneFace(const Cell& cell) const;
  void gather(std::size_t sample, std::vector<std::size_t>& out);
  std::size_t at(int x, int y) const { return static_cast<std::size_t>(y) * width_ + x; }

  int width_;
  std::span<const uint32_t> faceIds_;
  std::span<const uint8_t> needed_;
  std::vector<uint8_t> gatheredFlag_;
  std::size_t gathered_ = 0;
  std::vector<std::size_t> first_;
  std::vector<Cell> checking_;  // one face, corners and centre gathered in the last round
  std::vector<Cell> accepted_;  // interpolated from their corners
};

}  // namespace penumbra
