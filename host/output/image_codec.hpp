#pragma once
// The image files' codec as a table of functions: what the module penumbra_image_io (built from
// image_codec_oiio.cpp, through OpenImageIO) hands to image_module.cpp, which implements
// image_files.hpp with it.
//
// Why a module: OpenImageIO brings about 260 shared libraries (ffmpeg, OpenCV, OpenVDB, DCMTK,
// libheif, …). Linked into `penumbra`, their loading and relocation cost every process about
// 0.4 s of CPU before main() (`penumbra --version`: 0.05 s without them), though most runs never
// read or write an image. Loaded with dlopen, they cost only the processes that do, once.
#include <filesystem>
#include <string>

#include "image/images.hpp"
#include "output/radiance_hdr.hpp"

namespace penumbra {

// Raised whenever a field of ImageCodec changes, so that a stale module is refused.
inline constexpr int kImageCodecVersion = 1;
// The module's file name, looked for beside the running program and in the build folder.
inline constexpr const char* kImageModuleFile = "libpenumbra_image_io.so";
// The one symbol the module exports: extern "C" const ImageCodec* penumbra_image_codec().
inline constexpr const char* kImageCodecSymbol = "penumbra_image_codec";

// One entry per function of image_files.hpp, with its meaning and its errors.
struct ImageCodec {
  int version = 0;
  void (*writeRgbExr)(const std::filesystem::path&, const RgbImage&, const ImageMetadata&);
  void (*writeScalarExr)(const std::filesystem::path&, const ScalarImage&, const std::string&,
                         const ImageMetadata&);
  void (*writeFaceIdExr)(const std::filesystem::path&, const FaceIdImage&, const ImageMetadata&);
  void (*writeRadianceHdr)(const std::filesystem::path&, const RgbImage&, const RadianceHeader&);
  void (*writePng)(const std::filesystem::path&, const DisplayImage&, const ImageMetadata&);
  RgbImage (*readRgbExr)(const std::filesystem::path&);
  ScalarImage (*readScalarExr)(const std::filesystem::path&);
  FaceIdImage (*readFaceIdExr)(const std::filesystem::path&);
  ImageMetadata (*readImageMetadata)(const std::filesystem::path&);
};

}  // namespace penumbra
