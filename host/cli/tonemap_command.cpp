#include "cli/tonemap_command.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "cli/exit_status.hpp"
#include "output/image_files.hpp"
#include "output/tone_map_files.hpp"
#include "tonemap/tone_map.hpp"

namespace penumbra {
namespace {

void printStats(const ToneMapStats& s) {
  fmt::print(stderr, "penumbra: {} ({}x{}), black {}, {} regions\n", s.method, s.width, s.height,
             s.black, s.regions);
  if (s.method == "constraint") {
    fmt::print(stderr,
               "  {} variables ({} lattice), rows: {} strong ({} with three variables), {} medium, "
               "{} weak\n"
               "  {} outer iterations{}, {} at black, {} at white (raised by {:.3f} in log V)\n"
               "  residual rms/max (log V): strong {:.3g}/{:.3g}, medium {:.3g}/{:.3g}, weak "
               "{:.3g}/{:.3g}\n"
               "  seconds: build {:.3f}, solve {:.3f}, pixels {:.3f}\n",
               s.variables, s.vertices, s.strongRows, s.threeVariableRows, s.mediumRows, s.weakRows,
               s.outerIterations, s.converged ? "" : " (not converged)", s.atLowerBound,
               s.atUpperBound, s.raisedToWhite, s.strongRms, s.strongMax, s.mediumRms, s.mediumMax,
               s.weakRms, s.weakMax, s.buildSeconds, s.solveSeconds, s.pixelSeconds);
  }
  fmt::print(stderr, "  total {:.3f} s\n", s.totalSeconds);
}

int run(const ToneMapCommandOptions& options) {
  const RgbImage hdr = readRgbExr(options.input);
  FaceIdImage faces;
  const std::filesystem::path facesPath =
      options.faces.empty() ? facesBeside(options.input) : options.faces;
  if (options.display.method == DisplayMethod::Constraint || std::filesystem::exists(facesPath)) {
    faces = readFaceIdExr(facesPath);
  } else {
    // clip and linear need no regions: the whole image is one surface.
    faces = FaceIdImage(hdr.width, hdr.height);
    std::fill(faces.ids.begin(), faces.ids.end(), 1u);
  }
  ToneMapStats stats;
  const DisplayImage image = toneMap(hdr, faces, options.display, &stats);
  writeToneMapFiles(options.output, image, stats, {{"penumbra:source", options.input.string()}});
  if (options.verbose) printStats(stats);
  if (!stats.converged) {
    fmt::print(stderr, "penumbra: warning: the constraint solve stopped before converging\n");
  }
  return 0;
}

}  // namespace

std::filesystem::path facesBeside(const std::filesystem::path& input) {
  std::filesystem::path faces = input;
  return faces.replace_extension(".faceid.exr");
}

int runToneMapCommand(const ToneMapCommandOptions& options) {
  return cli::reportingErrors([&] { return run(options); });
}

}  // namespace penumbra
