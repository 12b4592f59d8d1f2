#include "render/indirect_sampling.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "radiosity/radiosity_solver.hpp"

namespace penumbra {

LatticePlan::LatticePlan(int width, int height, std::span<const uint32_t> faceIds,
                         std::span<const uint8_t> needed, int spacing)
    : width_(width),
      faceIds_(faceIds),
      needed_(needed),
      gatheredFlag_(static_cast<std::size_t>(width) * height, 0) {
  if (spacing < 1) {
    throw std::invalid_argument(
        fmt::format("the indirect lattice spacing must be 1 or more samples, got {}", spacing));
  }
  for (int y0 = 0; y0 < height; y0 += spacing)
    for (int x0 = 0; x0 < width; x0 += spacing)
      split(Cell{x0, std::min(x0 + spacing, width - 1), y0, std::min(y0 + spacing, height - 1)},
            first_);
  std::sort(first_.begin(), first_.end());
}

void LatticePlan::gather(std::size_t sample, std::vector<std::size_t>& out) {
  if (gatheredFlag_[sample] || !needed_[sample]) return;
  gatheredFlag_[sample] = 1;
  ++gathered_;
  out.push_back(sample);
}

bool LatticePlan::oneFace(const Cell& c) const {
  if (!needed_[at(c.x0, c.y0)]) return false;
  const uint32_t face = faceIds_[at(c.x0, c.y0)];
  for (int y = c.y0; y <= c.y1; ++y)
    for (int x = c.x0; x <= c.x1; ++x)
      if (!needed_[at(x, y)] || faceIds_[at(x, y)] != face) return false;
  return true;
}

void LatticePlan::quarter(const Cell& c, bool byFace, std::vector<std::size_t>& out) {
  // Cut in four (in two across a side of one sample); the quarters share their middle lines.
  const int xm = c.x1 - c.x0 > 1 ? (c.x0 + c.x1) / 2 : c.x1;
  const int ym = c.y1 - c.y0 > 1 ? (c.y0 + c.y1) / 2 : c.y1;
  std::vector<Cell> parts{{c.x0, xm, c.y0, ym}};
  if (xm < c.x1) parts.push_back({xm, c.x1, c.y0, ym});
  if (ym < c.y1) parts.push_back({c.x0, xm, ym, c.y1});
  if (xm < c.x1 && ym < c.y1) parts.push_back({xm, c.x1, ym, c.y1});
  for (const Cell& part : parts) byFace ? split(part, out) : check(part, out);
}

void LatticePlan::split(const Cell& c, std::vector<std::size_t>& out) {
  if (oneFace(c)) return check(c, out);
  if (c.x1 - c.x0 <= 1 && c.y1 - c.y0 <= 1) {
    for (int y = c.y0; y <= c.y1; ++y)
      for (int x = c.x0; x <= c.x1; ++x) gather(at(x, y), out);
    return;
  }
  quarter(c, true, out);
}

void LatticePlan::check(const Cell& c, std::vector<std::size_t>& out) {
  if (c.x1 - c.x0 <= 2 && c.y1 - c.y0 <= 2) {
    // A centre that decides for at most four other samples: gather them all.
    for (int y = c.y0; y <= c.y1; ++y)
      for (int x = c.x0; x <= c.x1; ++x) gather(at(x, y), out);
    return;
  }
  const int xm = (c.x0 + c.x1) / 2, ym = (c.y0 + c.y1) / 2;
  for (int y : {c.y0, ym, c.y1})
    for (int x : {c.x0, xm, c.x1}) gather(at(x, y), out);
  checking_.push_back(c);
}

std::vector<std::size_t> LatticePlan::next(std::span<const float> indirect,
                                           std::span<const float> direct) {
  std::vector<std::size_t> out;
  std::vector<Cell> checking;
  checking.swap(checking_);
  for (const Cell& c : checking) {
    const int xm = (c.x0 + c.x1) / 2, ym = (c.y0 + c.y1) / 2;
    const std::array<std::size_t, 4> corner{at(c.x0, c.y0), at(c.x1, c.y0), at(c.x0, c.y1),
                                            at(c.x1, c.y1)};
    // The centre and the four edge midpoints against the corners' bilinear interpolation: the
    // centre alone misses a surface curved one way along x and the other along y.
    double worst = 0.0;
    for (const auto& [x, y] : {std::pair{xm, ym}, {xm, c.y0}, {xm, c.y1}, {c.x0, ym}, {c.x1, ym}}) {
      const std::size_t m = at(x, y);
      if (m == corner[0] || m == corner[1] || m == corner[2] || m == corner[3]) continue;
      const double u = c.x1 > c.x0 ? double(x - c.x0) / (c.x1 - c.x0) : 0.0;
      const double v = c.y1 > c.y0 ? double(y - c.y0) / (c.y1 - c.y0) : 0.0;
      const std::array<double, 4> weight{(1 - u) * (1 - v), u * (1 - v), (1 - u) * v, u * v};
      const double total =
          direct[m] +
          photometric(Eigen::Vector3d(indirect[m * 3], indirect[m * 3 + 1], indirect[m * 3 + 2]));
      for (int ch = 0; ch < 3; ++ch) {
        double line = 0.0;
        for (int k = 0; k < 4; ++k) line += weight[k] * indirect[corner[k] * 3 + ch];
        worst = std::max(worst, std::abs(indirect[m * 3 + ch] - line) / total);
      }
    }
    if (worst <= kTolerance) {
      accepted_.push_back(c);
    } else {
      quarter(c, false, out);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

void LatticePlan::interpolate(std::span<float> values, int channels) const {
  for (const Cell& c : accepted_) {
    const std::array<std::size_t, 4> corner{at(c.x0, c.y0), at(c.x1, c.y0), at(c.x0, c.y1),
                                            at(c.x1, c.y1)};
    const double w = std::max(c.x1 - c.x0, 1), h = std::max(c.y1 - c.y0, 1);
    for (int y = c.y0; y <= c.y1; ++y)
      for (int x = c.x0; x <= c.x1; ++x) {
        const std::size_t i = at(x, y);
        if (gatheredFlag_[i]) continue;
        const double u = (x - c.x0) / w, v = (y - c.y0) / h;
        const std::array<double, 4> weight{(1 - u) * (1 - v), u * (1 - v), (1 - u) * v, u * v};
        for (int ch = 0; ch < channels; ++ch) {
          double sum = 0.0;
          for (int k = 0; k < 4; ++k) sum += weight[k] * values[corner[k] * channels + ch];
          values[i * channels + ch] = static_cast<float>(sum);
        }
      }
  }
}

}  // namespace penumbra
