#pragma once
// A PNG's 8-bit values as a viewer reads them (OpenImageIO), for the tests of the display step.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/images.hpp"

namespace penumbra::testing {

inline DisplayImage readPng(const std::filesystem::path& path) {
  auto input = OIIO::ImageInput::open(path.string());
  if (!input) throw std::runtime_error("cannot read " + path.string());
  DisplayImage image;
  image.width = input->spec().width, image.height = input->spec().height;
  image.channels = input->spec().nchannels;
  image.values.resize(static_cast<size_t>(image.width) * image.height * image.channels);
  input->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::UINT8, image.values.data());
  return image;
}

// sRGB's transfer function (IEC 61966-2-1) written out for the tests, apart from the library's
// (tonemap/display_model.hpp): linear share → code value in [0, 1], and back.
inline double srgbCodeOf(double linear) {
  return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1 / 2.4) - 0.055;
}
inline double srgbLinearOf(double code) {
  return code <= 0.04045 ? code / 12.92 : std::pow((code + 0.055) / 1.055, 2.4);
}

// The 8-bit code value (unrounded, 0-255) that a PNG of `penumbra tonemap` holds for a display V
// (a share of the display's white) on the default display (no ambient light) with black `black`.
inline double expectedCode(double v, double black) {
  return 255.0 * srgbCodeOf((v - black) / (1.0 - black));
}

// A big-endian 32-bit unsigned integer, as PNG stores every number.
inline uint32_t pngUint32(const uint8_t* p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | uint32_t{p[3]};
}

// One chunk of a PNG file as the PNG specification lays it out: 4-byte big-endian length, 4-byte
// type, data, CRC.
struct PngChunk {
  std::string type;
  std::vector<uint8_t> data;
};

// Every chunk of the file, in order, read from the bytes (no library): what a viewer sees.
inline std::vector<PngChunk> readPngChunks(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                   std::istreambuf_iterator<char>());
  const uint8_t signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  if (bytes.size() < 8 || !std::equal(signature, signature + 8, bytes.begin()))
    throw std::runtime_error("not a PNG: " + path.string());
  std::vector<PngChunk> chunks;
  for (size_t at = 8; at + 12 <= bytes.size();) {
    const uint32_t length = pngUint32(&bytes[at]);
    if (at + 12 + length > bytes.size()) throw std::runtime_error("truncated " + path.string());
    PngChunk chunk;
    chunk.type.assign(bytes.begin() + at + 4, bytes.begin() + at + 8);
    chunk.data.assign(bytes.begin() + at + 8, bytes.begin() + at + 8 + length);
    chunks.push_back(std::move(chunk));
    at += 12 + length;
  }
  return chunks;
}

}  // namespace penumbra::testing
