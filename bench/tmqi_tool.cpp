// TMQI (tonemap/tmqi.hpp) and the halo measure (tonemap/halo.hpp) of any 8-bit display image of a
// render: ours or another operator's (bench/tmqi_office.sh). Prints one row.
//   usage: tmqi_tool VIEW.exr VIEW.faceid.exr IMAGE.png [--decode-gamma G | --decode-display]
//            how the halo measure reads what the display shows (its linear output, a share of its
//            white) from the 8-bit values: --decode-gamma G, values encoded as V^(1/G) (a gamma
//            display, as pfsgamma writes them); --decode-display, through the display model that
//            `penumbra tonemap` encodes for at its defaults (tonemap/display_model.hpp: sRGB's
//            transfer, black 0.02 of white); neither, the values themselves. TMQI reads the 8-bit
//            values as they are (as its authors do).
//          tmqi_tool --write-step DIR
//            writes DIR/step.exr and DIR/step.faceid.exr: two flat faces 1:100 beside a window
//            (tests/synthetic_images.hpp), 384×192
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>

#include "output/image_files.hpp"
#include "tests/png_reader.hpp"
#include "tests/synthetic_images.hpp"
#include "tonemap/display_model.hpp"
#include "tonemap/display_spaces.hpp"
#include "tonemap/halo.hpp"
#include "tonemap/tmqi.hpp"

namespace {

using namespace penumbra;

// What the display shows for a code value in [0, 1], as a share of its white.
using Decode = std::function<double(double)>;

// The display's V per pixel: the largest of the colour channels / 255, decoded.
ScalarImage displayedValue(const DisplayImage& image, const Decode& decode) {
  ScalarImage v(image.width, image.height);
  const int colours = std::min(3, image.channels);
  for (size_t i = 0; i < v.values.size(); ++i) {
    int largest = 0;
    for (int c = 0; c < colours; ++c) {
      largest = std::max<int>(largest, image.values[i * image.channels + c]);
    }
    v.values[i] = static_cast<float>(decode(largest / 255.0));
  }
  return v;
}

// One row: S, N, Q, then the halo measure's overshoot, undershoot, mean deviation and regions.
std::string judge(const std::filesystem::path& exr, const std::filesystem::path& faceIds,
                  const std::filesystem::path& png, const Decode& decode) {
  const RgbImage hdr = readRgbExr(exr);
  const FaceIdImage faces = readFaceIdExr(faceIds);
  const DisplayImage image = testing::readPng(png);
  if (image.width != hdr.width || image.height != hdr.height) {
    throw std::runtime_error("the image is not the size of the render");
  }
  const TmqiScore score = toneMappedQuality(luminanceOf(hdr), lumaOf(image));
  ScalarImage spaceZero(hdr.width, hdr.height);
  spaceZero.values = displaySpaces(hdr, 0.02).value0;
  const HaloMeasure halo = measureHalos(spaceZero, faces, displayedValue(image, decode));
  char row[400];
  std::snprintf(row, sizeof row,
                "S %.4f  N %.4f  Q %.4f  halo +%.4f -%.4f mean %.4f (%d regions)  S_l %.3f %.3f "
                "%.3f %.3f %.3f  luma %.1f (%.3f)  block sigma %.1f (%.3f)",
                score.structuralFidelity, score.naturalness, score.quality, halo.overshoot,
                halo.undershoot, halo.meanDeviation, halo.regions, score.scaleFidelity[0],
                score.scaleFidelity[1], score.scaleFidelity[2], score.scaleFidelity[3],
                score.scaleFidelity[4], score.naturalnessFactors.meanLuma,
                score.naturalnessFactors.brightness, score.naturalnessFactors.blockDeviation,
                score.naturalnessFactors.contrast);
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
    const bool gammaGiven = argc == 6 && !std::strcmp(argv[4], "--decode-gamma");
    const bool displayGiven = argc == 5 && !std::strcmp(argv[4], "--decode-display");
    if (argc != 4 && !gammaGiven && !displayGiven) {
      std::cerr << "usage: tmqi_tool VIEW.exr VIEW.faceid.exr IMAGE.png [--decode-gamma G | "
                   "--decode-display]\n"
                   "       tmqi_tool --write-step DIR\n";
      return 1;
    }
    Decode decode = [](double code) { return code; };
    if (gammaGiven) {
      const double gamma = std::atof(argv[5]);
      decode = [gamma](double code) { return std::pow(code, gamma); };
    } else if (displayGiven) {
      const DisplayModel display;  // the tone map's defaults
      decode = [display](double code) { return display.luminance(code) / display.brightest(); };
    }
    std::cout << judge(argv[1], argv[2], argv[3], decode) << "\n";
  } catch (const std::exception& e) {
    std::cerr << "tmqi_tool: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
