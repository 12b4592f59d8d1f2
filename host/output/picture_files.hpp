#pragma once
// Pictures (charts, heat maps, the surfaces view) written where a failure to draw them is caught:
// VTK aborts the whole process when its X display is missing or goes away, so the caller's
// drawing runs in a child process (cluster/child_process.hpp) after the results are written. A
// record beside the pictures holds a fingerprint of the data each shows, so that a rerun draws
// only the pictures that are missing or show other data.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace penumbra {

struct PictureFile {
  std::string fileName;     // in the directory
  std::string fingerprint;  // of the data it shows (Fnv1a hex)
};

struct PicturesWritten {
  std::size_t drawn = 0;             // by this call
  std::size_t kept = 0;              // already there, showing the same data
  std::vector<std::string> missing;  // file names the drawing did not write
  std::string why;                   // the drawing's error, when some are missing
};

// Draws the named pictures, each into `directory` / name. May throw, or stop halfway: the files
// that are there count.
using PictureDrawing = std::function<void(const std::vector<std::string>& fileNames,
                                          const std::filesystem::path& directory)>;

// The pictures in `directory` (created if missing): one that is there and whose fingerprint the
// record `recordName` beside it holds is kept; the others are drawn with `draw` into a staging
// folder and renamed into place, with the record. A drawing that fails halfway costs only the
// pictures it did not draw: those are named in `missing`, so that the next call draws only them.
// A drawing that throws is called once more for the pictures it left.
PicturesWritten writePictures(const std::filesystem::path& directory, const std::string& recordName,
                              const std::vector<PictureFile>& pictures, const PictureDrawing& draw);

// `draw` in a child process: an abort there (signal 6) becomes an exception of this process.
PictureDrawing inChildProcess(PictureDrawing draw);

// "2 pictures not drawn (a.png, b.png): <why>", `noun` being the singular ("picture"); "" when
// none is missing.
std::string missingPictures(const PicturesWritten& written, const std::string& noun);

}  // namespace penumbra
