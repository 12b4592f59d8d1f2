#pragma once
// Image files through OpenImageIO, which is loaded the first time one is read or written (the
// module penumbra_image_io, image_codec.hpp says why). Every writer goes through a temporary name
// in the same folder and renames it when complete, so that a failed or killed run never leaves a
// partial image under the final name. Errors throw std::runtime_error naming the file.
//
//   <view>.exr            linear RGB, 32-bit float, channels R G B (cd/m² for renders)
//   <view>.<aov>.exr      one 32-bit float channel named after the AOV (e.g. "E" in lx)
//   <view>.faceid.exr     one 32-bit unsigned integer channel "id" (FaceIdImage)
//   <view>.hdr            Radiance RGBE of radiance, L / 179 (about 1 % precision), with the
//                         camera as VIEW= (radiance_hdr.hpp; written without OpenImageIO)
//   <view>.png            8-bit display values
#include <filesystem>
#include <string>

#include "image/images.hpp"
#include "output/radiance_hdr.hpp"

namespace penumbra {

void writeRgbExr(const std::filesystem::path& path, const RgbImage& image,
                 const ImageMetadata& metadata = {});
void writeScalarExr(const std::filesystem::path& path, const ScalarImage& image,
                    const std::string& channel, const ImageMetadata& metadata = {});
void writeFaceIdExr(const std::filesystem::path& path, const FaceIdImage& image,
                    const ImageMetadata& metadata = {});
// `luminance` in cd/m²; the file holds radiance, L / 179 (radiance_hdr.hpp says why).
void writeRadianceHdr(const std::filesystem::path& path, const RgbImage& luminance,
                      const RadianceHeader& header = {});
void writePng(const std::filesystem::path& path, const DisplayImage& image,
              const ImageMetadata& metadata = {});

// Readers for the formats above. readRgbExr takes the first three channels of any float image
// (a one-channel image is read as grey); readFaceIdExr wants exactly one channel.
RgbImage readRgbExr(const std::filesystem::path& path);
ScalarImage readScalarExr(const std::filesystem::path& path);
FaceIdImage readFaceIdExr(const std::filesystem::path& path);
// The header's string attributes (those written as metadata above, among others).
ImageMetadata readImageMetadata(const std::filesystem::path& path);

}  // namespace penumbra
