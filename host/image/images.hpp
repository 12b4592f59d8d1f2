#pragma once
// Images as plain values, shared by the stages that make them (render), change them (tonemap) and
// write them (output). Rows run top to bottom, pixels left to right; (0, 0) is the top-left pixel,
// as in OpenEXR and PNG.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace penumbra {

// Linear RGB, three floats per pixel (R, G, B). Renders hold luminance in cd/m² per channel.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<float> rgb;

  RgbImage() = default;
  RgbImage(int w, int h) : width(w), height(h), rgb(static_cast<size_t>(w) * h * 3, 0.0f) {}
  float* pixel(int x, int y) { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
  const float* pixel(int x, int y) const { return &rgb[(static_cast<size_t>(y) * width + x) * 3]; }
};

// One float per pixel (an AOV such as illuminance in lx).
struct ScalarImage {
  int width = 0, height = 0;
  std::vector<float> values;

  ScalarImage() = default;
  ScalarImage(int w, int h) : width(w), height(h), values(static_cast<size_t>(w) * h, 0.0f) {}
  float& at(int x, int y) { return values[static_cast<size_t>(y) * width + x]; }
  float at(int x, int y) const { return values[static_cast<size_t>(y) * width + x]; }
};

// Which polyhedron face each pixel shows. 0 is "no surface" (the ray left the scene); a face has
// the id index + 1, where index counts the faces of the scene's solids in order and then those of
// its sources (see render/face_ids.hpp). Only equality is meaningful to the tone map: two pixels
// with the same id show the same face, and a change of id is a visible edge.
struct FaceIdImage {
  static constexpr uint32_t kNoSurface = 0;
  int width = 0, height = 0;
  std::vector<uint32_t> ids;

  FaceIdImage() = default;
  FaceIdImage(int w, int h) : width(w), height(h), ids(static_cast<size_t>(w) * h, kNoSurface) {}
  uint32_t& at(int x, int y) { return ids[static_cast<size_t>(y) * width + x]; }
  uint32_t at(int x, int y) const { return ids[static_cast<size_t>(y) * width + x]; }
};

// 8-bit display values (what a PNG holds), `channels` per pixel.
struct DisplayImage {
  int width = 0, height = 0, channels = 3;
  std::vector<uint8_t> values;
};

// Name/value pairs written into an image file's header (the view, the scene, how it was made).
using ImageMetadata = std::vector<std::pair<std::string, std::string>>;

}  // namespace penumbra
