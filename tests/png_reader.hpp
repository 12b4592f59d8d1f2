#pragma once
// A PNG's 8-bit values as a viewer reads them (OpenImageIO), for the tests of the display step.
#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <stdexcept>

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

}  // namespace penumbra::testing
