#pragma once
// Per-case outputs of a sweep beyond the grid files: plots today (viz/), renders later. The
// sweep runner (host/study) knows them only through this interface, so that host/ never
// includes viz/: the command line (main.cpp) hands the runner the writers this binary has, and a
// study asks for them by name (`plots: true` asks for "plots").
#include <filesystem>
#include <string>
#include <vector>

#include "grid/run_report.hpp"
#include "output/picture_files.hpp"
#include "scene/scene.hpp"

namespace penumbra {

class CaseOutputWriter {
 public:
  virtual ~CaseOutputWriter() = default;

  // The study key that asks for this output ("plots"). It names the output in messages, in
  // study.json and in every case's fingerprint (a case drawn without it is not finished with it).
  virtual std::string name() const = 0;

  // Why this writer cannot work on this machine (e.g. no display for VTK), or "" when it can.
  // Asked once before the first case: an output that cannot be written is left out of the whole
  // run (and said so), rather than failing a sweep halfway.
  virtual std::string unavailable() const { return ""; }

  // Writes the case's files into `directory`: its staged case folder, which already holds the
  // files `penumbra grid` writes (summary.json, <grid>.csv, ...). `scene` is the case's scene
  // (its parameter values applied), `report` what was computed for it. Returns the images to list
  // in results.csv, relative to `directory`. Throws std::runtime_error when it fails: the case is
  // then not finished and nothing of it appears. Not const: a writer may keep a device or other
  // state from one case to the next.
  virtual std::vector<std::string> write(const Scene& scene, const RunReport& report,
                                         const std::filesystem::path& directory) = 0;

  // Draws the pictures of the finished case folder `directory` that are not there yet: those whose
  // drawing may end the process that draws them (VTK without its display), so they are drawn
  // after the case's results are in place, where that failure is caught
  // (output/picture_files.hpp). Called after each case is written and, on every later run, for
  // the cases finished before it, so that a rerun draws only what is missing. The images it
  // draws are among those write() listed. Returns what it drew, kept and could not draw.
  virtual PicturesWritten drawPictures(const Scene& /*scene*/,
                                       const std::filesystem::path& /*directory*/) {
    return {};
  }
};

}  // namespace penumbra
