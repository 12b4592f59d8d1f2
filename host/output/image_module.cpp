#include <dlfcn.h>
#include <unistd.h>

#include <fmt/format.h>

#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "output/image_codec.hpp"
#include "output/image_files.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// Where the module may be: beside the running program (the build folder's `penumbra` and tests,
// or an installed copy with its module), then the build folder this library was built in.
std::vector<fs::path> moduleCandidates() {
  std::vector<fs::path> candidates;
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (!error) candidates.push_back(program.parent_path() / kImageModuleFile);
  candidates.push_back(fs::path(PENUMBRA_IMAGE_MODULE_DIR) / kImageModuleFile);
  return candidates;
}

// Loads the module once per process; later calls return the same table. The module stays loaded
// until the process ends (OpenImageIO keeps plugins and threads of its own).
const ImageCodec& imageCodec() {
  static const ImageCodec* codec = nullptr;
  static std::string failure;
  static std::once_flag once;
  std::call_once(once, [] {
    std::string tried;
    for (const fs::path& candidate : moduleCandidates()) {
      void* module = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
      if (module == nullptr) {
        tried += fmt::format("\n  {}: {}", candidate.string(), dlerror());
        continue;
      }
      using Entry = const ImageCodec* (*)();
      const auto entry = reinterpret_cast<Entry>(dlsym(module, kImageCodecSymbol));
      const ImageCodec* table = entry != nullptr ? entry() : nullptr;
      if (table == nullptr || table->version != kImageCodecVersion) {
        tried += fmt::format("\n  {}: not penumbra's image module of this version (rebuild it)",
                             candidate.string());
        dlclose(module);
        continue;
      }
      codec = table;
      return;
    }
    failure = fmt::format(
        "cannot load penumbra's image module {} (it reads and writes EXR, PNG "
        "and HDR through OpenImageIO); tried:{}",
        kImageModuleFile, tried);
  });
  if (codec == nullptr) throw std::runtime_error(failure);
  return *codec;
}

}  // namespace

void writeRgbExr(const fs::path& path, const RgbImage& image, const ImageMetadata& metadata) {
  imageCodec().writeRgbExr(path, image, metadata);
}

void writeScalarExr(const fs::path& path, const ScalarImage& image, const std::string& channel,
                    const ImageMetadata& metadata) {
  imageCodec().writeScalarExr(path, image, channel, metadata);
}

void writeFaceIdExr(const fs::path& path, const FaceIdImage& image, const ImageMetadata& metadata) {
  imageCodec().writeFaceIdExr(path, image, metadata);
}

void writeRadianceHdr(const fs::path& path, const RgbImage& luminance,
                      const RadianceHeader& header) {
  imageCodec().writeRadianceHdr(path, luminance, header);
}

void writePng(const fs::path& path, const DisplayImage& image, const ImageMetadata& metadata) {
  imageCodec().writePng(path, image, metadata);
}

RgbImage readRgbExr(const fs::path& path) {
  return imageCodec().readRgbExr(path);
}

ScalarImage readScalarExr(const fs::path& path) {
  return imageCodec().readScalarExr(path);
}

FaceIdImage readFaceIdExr(const fs::path& path) {
  return imageCodec().readFaceIdExr(path);
}

ImageMetadata readImageMetadata(const fs::path& path) {
  return imageCodec().readImageMetadata(path);
}

}  // namespace penumbra
