// The share of visible edges whose contrast a display image keeps (tonemap/edge_contrast.hpp), for
// any 8-bit image of a render: ours or another operator's (bench/pfstmo_compare.sh). Prints JSON.
//   usage: edge_contrast_tool VIEW.exr VIEW.faceid.exr IMAGE.png [--black B] [--tolerance T]
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <nlohmann/json.hpp>

#include <OpenImageIO/imageio.h>

#include "output/image_files.hpp"
#include "tonemap/edge_contrast.hpp"

int main(int argc, char** argv) {
  using namespace penumbra;
  if (argc < 4) {
    std::cerr << "usage: edge_contrast_tool VIEW.exr VIEW.faceid.exr IMAGE.png [--black B] "
                 "[--tolerance T]\n";
    return 1;
  }
  double black = 0.02, tolerance = 0.05;
  for (int i = 4; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--black")) black = std::atof(argv[i + 1]);
    if (!std::strcmp(argv[i], "--tolerance")) tolerance = std::atof(argv[i + 1]);
  }
  try {
    const RgbImage hdr = readRgbExr(argv[1]);
    const FaceIdImage faces = readFaceIdExr(argv[2]);
    // Any 8-bit image: read through OpenImageIO as bytes, V = the largest channel.
    auto input = OIIO::ImageInput::open(argv[3]);
    if (!input) throw std::runtime_error(std::string("cannot read ") + argv[3]);
    const OIIO::ImageSpec& spec = input->spec();
    DisplayImage image;
    image.width = spec.width, image.height = spec.height,
    image.channels = std::min(3, spec.nchannels);
    std::vector<uint8_t> all(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, all.data());
    image.values.resize(static_cast<size_t>(spec.width) * spec.height * image.channels);
    for (size_t p = 0; p < static_cast<size_t>(spec.width) * spec.height; ++p) {
      for (int c = 0; c < image.channels; ++c) {
        image.values[p * image.channels + c] = all[p * spec.nchannels + c];
      }
    }
    if (image.width != hdr.width || image.height != hdr.height) {
      throw std::runtime_error("the image is not the size of the render");
    }
    // A pixel at 0 has no ratio: count it as the display's black.
    // The PNG as `penumbra tonemap` writes it with its default display (100 cd/m², no ambient).
    ScalarImage v = displayValueOf(image, DisplayModel{100.0, black, 0.0});
    for (float& x : v.values) x = std::max(x, 0.5f / 255);
    const EdgeContrastShare share = measureEdgeContrast(hdr, faces, v, black, tolerance);
    std::cout << nlohmann::json{{"image", argv[3]},
                                {"edges", share.edges},
                                {"kept", share.kept},
                                {"share", share.share()},
                                {"tolerance", tolerance}}
                     .dump()
              << "\n";
  } catch (const std::exception& e) {
    std::cerr << "edge_contrast_tool: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
