#include "output/image_codec.hpp"

#include <unistd.h>

#include <cstring>
#include <fstream>
#include <functional>
#include <stdexcept>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>

// The image files through OpenImageIO, compiled into the module penumbra_image_io only
// (image_codec.hpp says why); image_module.cpp forwards image_files.hpp's functions here.
namespace penumbra::image_codec {
namespace {

namespace fs = std::filesystem;
using OIIO::ImageInput;
using OIIO::ImageOutput;
using OIIO::ImageSpec;
using OIIO::TypeDesc;

// A hidden sibling with the same extension: OpenImageIO picks the format by extension, and the
// rename into place stays on one file system.
fs::path temporaryName(const fs::path& path) {
  return path.parent_path() /
         fmt::format(".{}.partial-{}{}", path.stem().string(), getpid(), path.extension().string());
}

// The complete file at `temporary` takes the name `path`; on failure it is removed.
void moveIntoPlace(const fs::path& temporary, const fs::path& path) {
  std::error_code renameError;
  fs::rename(temporary, path, renameError);
  if (renameError) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error(
        fmt::format("cannot write {}: {}", path.string(), renameError.message()));
  }
}

void writeImage(const fs::path& path, ImageSpec spec, const void* pixels,
                const ImageMetadata& metadata) {
  for (const auto& [name, value] : metadata) spec.attribute(name, value);
  const fs::path temporary = temporaryName(path);
  auto output = ImageOutput::create(path.string());
  if (!output) {
    throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(), OIIO::geterror()));
  }
  bool ok = output->open(temporary.string(), spec) && output->write_image(spec.format, pixels);
  const std::string error = ok ? std::string() : output->geterror();
  ok = output->close() && ok;
  if (!ok) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error(fmt::format("cannot write {}: {}", path.string(),
                                         error.empty() ? output->geterror() : error));
  }
  moveIntoPlace(temporary, path);
}

ImageSpec floatSpec(int width, int height, int channels) {
  ImageSpec spec(width, height, channels, TypeDesc::FLOAT);
  spec.attribute("compression", "zip");
  return spec;
}

void checkSize(const fs::path& path, int width, int height, size_t values, int channels) {
  if (width <= 0 || height <= 0 ||
      values != static_cast<size_t>(width) * static_cast<size_t>(height) * channels) {
    throw std::runtime_error(fmt::format("cannot write {}: a {} × {} image with {} values",
                                         path.string(), width, height, values));
  }
}

// Opens `path` and reads all of it as `type`, `channels` per pixel (channels the file lacks are
// not filled: callers ask for what the file has). Returns the spec.
ImageSpec readImage(const fs::path& path, TypeDesc type, int channels,
                    const std::function<void*(const ImageSpec&)>& allocate) {
  auto input = ImageInput::open(path.string());
  if (!input) {
    throw std::runtime_error(fmt::format("cannot read {}: {}", path.string(), OIIO::geterror()));
  }
  const ImageSpec spec = input->spec();
  void* pixels = allocate(spec);
  const int wanted = std::min(channels, spec.nchannels);
  if (!input->read_image(0, 0, 0, wanted, type, pixels)) {
    throw std::runtime_error(fmt::format("cannot read {}: {}", path.string(), input->geterror()));
  }
  return spec;
}

}  // namespace

void writeRgbExr(const fs::path& path, const RgbImage& image, const ImageMetadata& metadata) {
  checkSize(path, image.width, image.height, image.rgb.size(), 3);
  ImageSpec spec = floatSpec(image.width, image.height, 3);
  spec.channelnames = {"R", "G", "B"};
  writeImage(path, spec, image.rgb.data(), metadata);
}

void writeScalarExr(const fs::path& path, const ScalarImage& image, const std::string& channel,
                    const ImageMetadata& metadata) {
  checkSize(path, image.width, image.height, image.values.size(), 1);
  ImageSpec spec = floatSpec(image.width, image.height, 1);
  spec.channelnames = {channel};
  writeImage(path, spec, image.values.data(), metadata);
}

void writeFaceIdExr(const fs::path& path, const FaceIdImage& image, const ImageMetadata& metadata) {
  checkSize(path, image.width, image.height, image.ids.size(), 1);
  ImageSpec spec(image.width, image.height, 1, TypeDesc::UINT32);
  spec.channelnames = {"id"};
  spec.attribute("compression", "zip");
  writeImage(path, spec, image.ids.data(), metadata);
}

void writeRadianceHdr(const fs::path& path, const RgbImage& luminance,
                      const RadianceHeader& header) {
  checkSize(path, luminance.width, luminance.height, luminance.rgb.size(), 3);
  const std::string bytes = encodeRadianceHdr(luminance, header);
  const fs::path temporary = temporaryName(path);
  std::ofstream out(temporary, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw std::runtime_error(fmt::format("cannot write {}", path.string()));
  }
  moveIntoPlace(temporary, path);
}

void writePng(const fs::path& path, const DisplayImage& image, const ImageMetadata& metadata) {
  checkSize(path, image.width, image.height, image.values.size(), image.channels);
  writeImage(path, ImageSpec(image.width, image.height, image.channels, TypeDesc::UINT8),
             image.values.data(), metadata);
}

RgbImage readRgbExr(const fs::path& path) {
  RgbImage image;
  std::vector<float> buffer;
  const ImageSpec spec = readImage(path, TypeDesc::FLOAT, 3, [&](const ImageSpec& s) -> void* {
    buffer.assign(static_cast<size_t>(s.width) * s.height * std::min(3, s.nchannels), 0.0f);
    return buffer.data();
  });
  image = RgbImage(spec.width, spec.height);
  const int channels = std::min(3, spec.nchannels);
  for (size_t i = 0; i < static_cast<size_t>(spec.width) * spec.height; ++i) {
    for (int c = 0; c < 3; ++c)
      image.rgb[i * 3 + c] = buffer[i * channels + std::min(c, channels - 1)];
  }
  return image;
}

ScalarImage readScalarExr(const fs::path& path) {
  ScalarImage image;
  readImage(path, TypeDesc::FLOAT, 1, [&](const ImageSpec& s) -> void* {
    image = ScalarImage(s.width, s.height);
    return image.values.data();
  });
  return image;
}

FaceIdImage readFaceIdExr(const fs::path& path) {
  FaceIdImage image;
  readImage(path, TypeDesc::UINT32, 1, [&](const ImageSpec& s) -> void* {
    if (s.nchannels != 1) {
      throw std::runtime_error(
          fmt::format("cannot read {}: a face-id image has one channel, this one has {}",
                      path.string(), s.nchannels));
    }
    image = FaceIdImage(s.width, s.height);
    return image.ids.data();
  });
  return image;
}

ImageMetadata readImageMetadata(const fs::path& path) {
  auto input = ImageInput::open(path.string());
  if (!input) {
    throw std::runtime_error(fmt::format("cannot read {}: {}", path.string(), OIIO::geterror()));
  }
  ImageMetadata metadata;
  for (const auto& attribute : input->spec().extra_attribs) {
    if (attribute.type() == TypeDesc::STRING) {
      metadata.emplace_back(attribute.name().string(), attribute.get_string());
    }
  }
  return metadata;
}

}  // namespace penumbra::image_codec

// The module's one exported symbol.
extern "C" __attribute__((visibility("default"))) const penumbra::ImageCodec*
penumbra_image_codec() {
  namespace c = penumbra::image_codec;
  static const penumbra::ImageCodec codec{penumbra::kImageCodecVersion,
                                          c::writeRgbExr,
                                          c::writeScalarExr,
                                          c::writeFaceIdExr,
                                          c::writeRadianceHdr,
                                          c::writePng,
                                          c::readRgbExr,
                                          c::readScalarExr,
                                          c::readFaceIdExr,
                                          c::readImageMetadata};
  return &codec;
}
