#pragma once
// Synthetic HDR images with face ids, for the tone-map tests and bench/tonemap_bench.cpp, until
// real renders exist: a staircase of flat regions, and a room-like view (window, luminaires,
// walls with falloff, boxes with penumbra-like ramps on the floor).
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "image/images.hpp"

namespace penumbra::testing {

struct HdrScene {
  RgbImage hdr;
  FaceIdImage faces;
};

// Vertical stripes of equal width, each flat, each `ratios[i]` times brighter than the one before.
inline HdrScene staircase(const std::vector<double>& ratios, int stripeWidth, int height,
                          double darkest) {
  const int stripes = static_cast<int>(ratios.size()) + 1;
  HdrScene scene{RgbImage(stripes * stripeWidth, height),
                 FaceIdImage(stripes * stripeWidth, height)};
  double value = darkest;
  for (int s = 0; s < stripes; ++s) {
    if (s > 0) value *= ratios[s - 1];
    for (int y = 0; y < height; ++y) {
      for (int x = s * stripeWidth; x < (s + 1) * stripeWidth; ++x) {
        float* p = scene.hdr.pixel(x, y);
        p[0] = p[1] = p[2] = static_cast<float>(value);
        scene.faces.at(x, y) = static_cast<uint32_t>(s + 1);
      }
    }
  }
  return scene;
}

using Point = std::array<double, 2>;

// Fills the convex polygon (counter-clockwise or clockwise) with face `id` and the luminance
// `shade(x, y)` times `colour`; later polygons cover earlier ones, as nearer faces do.
template <typename Shade>
void fillPolygon(HdrScene& scene, const std::vector<Point>& polygon, uint32_t id,
                 std::array<double, 3> colour, Shade shade) {
  double x0 = 1e30, x1 = -1e30, y0 = 1e30, y1 = -1e30;
  for (const Point& p : polygon) {
    x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]),
    y1 = std::max(y1, p[1]);
  }
  const int w = scene.hdr.width, h = scene.hdr.height;
  for (int y = std::max(0, int(std::floor(y0))); y <= std::min(h - 1, int(std::ceil(y1))); ++y) {
    for (int x = std::max(0, int(std::floor(x0))); x <= std::min(w - 1, int(std::ceil(x1))); ++x) {
      const double px = x + 0.5, py = y + 0.5;
      int sign = 0;
      bool inside = true;
      for (size_t i = 0; i < polygon.size() && inside; ++i) {
        const Point& a = polygon[i];
        const Point& b = polygon[(i + 1) % polygon.size()];
        const double cross = (b[0] - a[0]) * (py - a[1]) - (b[1] - a[1]) * (px - a[0]);
        const int s = cross > 0 ? 1 : cross < 0 ? -1 : 0;
        if (s != 0 && sign != 0 && s != sign) inside = false;
        if (s != 0) sign = s;
      }
      if (!inside) continue;
      const double l = shade(px, py);
      float* p = scene.hdr.pixel(x, y);
      for (int c = 0; c < 3; ++c) p[c] = static_cast<float>(l * colour[c]);
      scene.faces.at(x, y) = id;
    }
  }
}

// A room seen from the door: ceiling, floor, three walls, a window on the left wall (about 1e4
// times the darkest surfaces), ceiling luminaires, and `boxes` pieces of furniture (three faces
// each) whose shadows fall on the floor as smooth ramps (penumbrae). Deterministic for a seed.
inline HdrScene roomView(int width, int height, int boxes, unsigned seed = 5) {
  HdrScene scene{RgbImage(width, height), FaceIdImage(width, height)};
  const double w = width, h = height;
  const Point tl{0.3 * w, 0.25 * h}, tr{0.7 * w, 0.25 * h}, br{0.7 * w, 0.7 * h},
      bl{0.3 * w, 0.7 * h};
  const Point ctl{0, 0}, ctr{w, 0}, cbr{w, h}, cbl{0, h};
  const Point windowCentre{0.12 * w, 0.45 * h};
  const auto falloff = [&](double base) {
    return [=](double x, double y) {
      const double dx = (x - windowCentre[0]) / w, dy = (y - windowCentre[1]) / h;
      return base / (0.05 + dx * dx + dy * dy);
    };
  };
  uint32_t id = 1;
  fillPolygon(scene, {ctl, ctr, tr, tl}, id++, {1, 1, 1}, falloff(0.4));         // ceiling
  fillPolygon(scene, {ctl, tl, bl, cbl}, id++, {0.9, 0.9, 0.85}, falloff(2));    // left wall
  fillPolygon(scene, {tr, ctr, cbr, br}, id++, {0.85, 0.9, 0.9}, falloff(1.2));  // right wall
  fillPolygon(scene, {tl, tr, br, bl}, id++, {0.95, 0.9, 0.8}, falloff(1.5));    // back wall
  // The floor, with the boxes' shadows as ramps (set below, before the boxes cover it).
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  struct Box {
    double x, y, size;
  };
  std::vector<Box> placed;
  for (int b = 0; b < boxes; ++b) {
    placed.push_back({(0.12 + 0.76 * unit(random)) * w, (0.74 + 0.22 * unit(random)) * h,
                      (0.03 + 0.05 * unit(random)) * std::min(w, h)});
  }
  std::sort(placed.begin(), placed.end(), [](const Box& a, const Box& b) { return a.y < b.y; });
  const auto floorShade = [&](double x, double y) {
    double l = falloff(3)(x, y);
    for (const Box& box : placed) {
      // Penumbra: a smooth step over one box size to the right of each box (away from the window).
      const double u = (x - box.x) / box.size, v = (y - box.y) / box.size;
      if (u > 0 && u < 3 && std::abs(v) < 1.2) l *= 0.3 + 0.7 * std::clamp(u / 3, 0.0, 1.0);
    }
    return l;
  };
  fillPolygon(scene, {bl, br, cbr, cbl}, id++, {0.7, 0.6, 0.5}, floorShade);
  // The window and two luminaires: sources, the brightest faces of the view.
  fillPolygon(scene,
              {{0.06 * w, 0.3 * h}, {0.2 * w, 0.36 * h}, {0.2 * w, 0.58 * h}, {0.06 * w, 0.62 * h}},
              id++, {0.9, 0.95, 1.0}, [](double, double) { return 8000.0; });
  for (double cx : {0.4, 0.6}) {
    fillPolygon(scene,
                {{(cx - 0.05) * w, 0.1 * h},
                 {(cx + 0.05) * w, 0.1 * h},
                 {(cx + 0.045) * w, 0.14 * h},
                 {(cx - 0.045) * w, 0.14 * h}},
                id++, {1, 1, 0.95}, [](double, double) { return 3000.0; });
  }
  for (const Box& box : placed) {
    const double s = box.size, x = box.x, y = box.y;
    const double top = 0.8 * s;
    const Point f0{x - s, y}, f1{x + s, y}, f2{x + s, y - top}, f3{x - s, y - top};
    const Point back0{x - 0.7 * s, y - top - 0.3 * s}, back1{x + 1.3 * s, y - top - 0.3 * s};
    const Point side{x + 1.3 * s, y - 0.3 * s};
    const double tint = 0.5 + 0.5 * unit(random);
    fillPolygon(scene, {f0, f1, f2, f3}, id++, {tint, 0.8, 0.7}, falloff(0.8));        // front
    fillPolygon(scene, {f3, f2, back1, back0}, id++, {tint, 0.8, 0.7}, falloff(1.6));  // top
    fillPolygon(scene, {f1, side, back1, f2}, id++, {tint, 0.8, 0.7}, falloff(0.4));   // side
  }
  return scene;
}

// Two flat faces side by side, 1:100 (1 and 100 cd/m², each `side` pixels wide, `stepHeight`
// tall), above a band `bandHeight` tall with no surface that holds a window (10⁴ cd/m², its own
// face, a square of half the band's height in its middle). The window sets the display's white,
// as in a room with one in view, so the step lies near black in the linear map; the band keeps
// the window from any edge with the step. The halo test and bench/tmqi_tool.
inline HdrScene stepBesideWindow(int side, int stepHeight, int bandHeight) {
  HdrScene scene = staircase({100.0}, side, stepHeight + bandHeight, 1.0);
  const int width = 2 * side, square = bandHeight / 2;
  const int x0 = side - square / 2, y0 = stepHeight + bandHeight / 4;
  for (int y = stepHeight; y < stepHeight + bandHeight; ++y) {
    for (int x = 0; x < width; ++x) {
      const bool window = y >= y0 && y < y0 + square && x >= x0 && x < x0 + square;
      float* p = scene.hdr.pixel(x, y);
      p[0] = p[1] = p[2] = window ? 1e4f : 0.0f;
      scene.faces.at(x, y) = window ? 3 : FaceIdImage::kNoSurface;
    }
  }
  return scene;
}

}  // namespace penumbra::testing
