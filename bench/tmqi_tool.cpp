// TMQI (tonemap/tmqi.hpp) and the halo measure (tonemap/halo.hpp) of any 8-bit display image of a
// render: ours or another operator's (bench/tmqi_office.sh). Prints one row.
//   usage: tmqi_tool VIEW.exr VIEW.faceid.exr IMAGE.png [--decode-gamma G]
//            --decode-gamma: the image's values are encoded for the display (V^(1/G)); the halo
//            measure reads V^G, the display's linear output. TMQI reads the 8-bit values as they
//            are (as its authors do).
//          tmqi_tool --write-step DIR
//            writes DIR/step.exr and DIR/step.faceid.exr: two flat faces 1:100 beside a window
//            (tests/synthetic_images.hpp), 384×192
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>

#include "output/image_files.hpp"
#include "tests/png_reader.hpp"
#include "tests/synthetic_images.hpp"
#include "tonemap/display_spaces.hpp"
#include "tonemap/halo.hpp"
#include "tonemap/tmqi.hpp"

namespace {

using namespace penumbra;

// The display's V per pixel: the largest of the colour channels / 255, decoded with `gamma`.
ScalarImage displayedValue(const DisplayImage& image, double gamma) {
  ScalarImage v(image.width, image.height);
  const int colours = std::min(3, image.channels);
  for (size_t i = 0; i < v.values.size(); ++i) {
    int largest = 0;
    for (int c = 0; c < colours; ++c) {
      largest = std::max<int>(largest, image.values[i * image.channels + c]);
    }
    v.values[i] = static_cast<float>(std::pow(largest / 255.0, gamma));
  }
  return v;
}

// One row: S, N, Q, then the halo measure's overshoot, undershoot, mean deviation and regions.
std::string judge(const std::filesystem::path& exr, const std::filesystem::path& faceIds,
                  const std::filesystem::path& png, double gamma) {
  const RgbImage hdr = readRgbExr(exr);
  const FaceIdImage faces = readFaceIdExr(faceIds);
  const DisplayImage image = testing::readPng(png);
  if (image.width != hdr.width || image.height != hdr.height) {
    throw std::runtime_error("the image is not the size of the render");
  }
  const TmqiScore score = toneMappedQuality(luminanceOf(hdr), lumaOf(image));
  ScalarImage spaceZero(hdr.width, hdr.height);
  spaceZero.values = displaySpaces(hdr, 0.02).value0;
  const HaloMeasure halo = measureHalos(spaceZero, faces, displayedValue(image, gamma));
  char row[300];
  std::snprintf(row, sizeof row,
                "S %.4f  N %.4f  Q %.4f  halo +%.4f -%.4f mean %.4f (%d regions)  S_l %.3f %.3f "
                "%.3f %.3f %.3f",
                score.structuralFidelity, score.naturalness, score.quality, halo.overshoot,
                halo.undershoot, halo.meanDeviation, halo.regions, score.scaleFidelity[0],
                score.scaleFidelity[1], score.scaleFidelity[2], score.scaleFidelity[3],
                score.scaleFidelity[4]);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 3 && !std::strcmp(argv[1], "--write-step")) {
      const testing::HdrScene step = testing::stepBesideWindow(192, 128, 64);
      writeRgbExr(std::filesystem::path(argv[2]) / "step.exr", step.hdr);
      writeFaceIdExr(std::filesystem::path(argv[2]) / "step.faceid.exr", step.faces);
      return 0;
    }
    if (argc != 4 && !(argc == 6 && !std::strcmp(argv[4], "--decode-gamma"))) {
      std::cerr << "usage: tmqi_tool VIEW.exr VIEW.faceid.exr IMAGE.png [--decode-gamma G]\n"
                   "       tmqi_tool --write-step DIR\n";
      return 1;
    }
    const double gamma = argc == 6 ? std::atof(argv[5]) : 1.0;
    std::cout << judge(argv[1], argv[2], argv[3], gamma) << "\n";
  } catch (const std::exception& e) {
    std::cerr << "tmqi_tool: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
