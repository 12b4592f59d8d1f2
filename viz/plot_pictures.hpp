#pragma once
// The PNGs of a plotted run (a heat map per planar grid, surfaces.png), drawn from the files in its
// folder (the grids' results, surfaces.vtp) after they are written, in a child process: VTK
// aborts the process drawing when its X display is missing or goes away, and that must cost
// neither the results nor the other files. plots.json beside them records what each picture shows,
// so that a rerun draws only the pictures that are missing (output/picture_files.hpp).
#include <filesystem>
#include <string>

#include "grid/run_report.hpp"
#include "output/picture_files.hpp"
#include "scene/scene.hpp"
#include "viz/plot_files.hpp"
#include "viz/plot_options.hpp"

namespace penumbra::viz {

inline constexpr const char* kPlotRecord = "plots.json";

// The pictures of `run` (the PNGs of plotFileNames) with the fingerprints of what they show: the
// data files they are drawn from (<grid>.vti, surfaces.vtp in `directory`), the metrics in their
// titles, what E includes, the scene file and its parameter values, and the drawing options.
std::vector<PictureFile> plotPictures(const RunReport& run, const Scene& scene,
                                      const PlotOptions& options,
                                      const std::filesystem::path& directory);

// Draws the pictures of `run` into `directory`, which holds its results and the files
// writePlotData wrote, those already there with the same data kept. `scene` is the run's scene
// (with its parameter values). Never throws for a picture that could not be drawn: it is named in
// the result's `missing`, with the signal or error in `why`.
PicturesWritten drawPlotPictures(const RunReport& run, const Scene& scene,
                                 const PlotOptions& options, const std::filesystem::path& directory,
                                 const PlotProgress& progress = {});

}  // namespace penumbra::viz
