// OpenImageIO and its ~260 shared libraries are loaded by the first image read or written
// (output/image_codec.hpp), not at the start of every process: this test program links only
// penumbra_host, as `penumbra` does.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "output/image_files.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

using penumbra::testing::TempDir;

// Whether a shared library whose file name contains `name` is mapped into this process.
bool mapped(const std::string& name) {
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line))
    if (line.find(name) != std::string::npos) return true;
  return false;
}

TEST(ImageModule, OpenImageIOIsLoadedByTheFirstImageOnly) {
  EXPECT_FALSE(mapped("libOpenImageIO")) << "linked in: every process pays for its libraries";
  TempDir dir("image-module");
  DisplayImage image;
  image.width = 4;
  image.height = 2;
  image.channels = 3;
  for (int i = 0; i < 24; ++i) image.values.push_back(static_cast<uint8_t>(10 * i));
  const auto png = dir.path() / "tiny.png";
  writePng(png, image, {{"penumbra:view", "test"}});
  EXPECT_TRUE(mapped("libpenumbra_image_io.so"));
  EXPECT_TRUE(mapped("libOpenImageIO"));
  // Through the module and back: the header's metadata as written.
  const ImageMetadata metadata = readImageMetadata(png);
  bool found = false;
  for (const auto& [name, value] : metadata) found |= name == "penumbra:view" && value == "test";
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace penumbra
