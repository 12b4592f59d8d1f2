#pragma once
// The files of a parameter sweep (docs/sweeps.md), written so that nothing is ever half there:
//   OUT/study.json, results.csv, design-explorer.csv   each replaced in one rename
//   OUT/cases/<id>/                                    a whole case folder appears in one rename
//   OUT/charts/*.png                                   drawn by a hook (viz/), staged like the rest
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "grid/run_report.hpp"
#include "output/case_output.hpp"
#include "output/line_chart.hpp"
#include "output/picture_files.hpp"
#include "scene/scene.hpp"

namespace penumbra {

struct ChartFile {
  LineChart chart;
  std::string fileName;  // in OUT/charts
};

// Draws a batch of charts, each into `directory` / fileName (viz::writeLineChart in a child
// process when the binary has viz/). May throw, or stop halfway: the files that are there count.
using ChartDrawing = std::function<void(const std::vector<ChartFile>& charts,
                                        const std::filesystem::path& directory)>;

struct ChartWriter {
  ChartDrawing draw;        // empty: this binary draws no charts (built without viz/)
  std::string unavailable;  // why charts cannot be drawn on this machine (no display), or ""
  explicit operator bool() const { return static_cast<bool>(draw); }
};

using ChartsWritten = PicturesWritten;

// Writes one finished case into `folder` (OUT/cases/<id>): the files `penumbra grid` writes, then
// those of every writer in `outputs`, in order, and last `case.json` (= `caseJson` with
// "images": the images the writers listed). Staged in a hidden sibling and renamed at the end; a
// stale folder of that name is removed first, and so are leftovers of killed runs of the same
// case. Throws std::runtime_error when two writers list the same image.
void writeCaseFolder(const std::filesystem::path& folder, const Scene& scene,
                     const RunReport& report, nlohmann::ordered_json caseJson,
                     const std::vector<CaseOutputWriter*>& outputs);

// Copies a finished case folder to `to` the same way (penumbra merge).
void copyCaseFolder(const std::filesystem::path& from, const std::filesystem::path& to);

// Writes (name, text) files into the directory `out` (created if missing), each replacing its
// namesake in one rename; other files stay.
void writeTextFiles(const std::filesystem::path& out,
                    const std::vector<std::pair<std::string, std::string>>& files);

// The charts in `directory`, by writePictures (charts.json beside them records a fingerprint of
// each chart's data): a writer that fails halfway costs only the charts it did not draw, and the
// next call draws only them.
ChartsWritten writeCharts(const std::filesystem::path& directory,
                          const std::vector<ChartFile>& charts, const ChartWriter& writer);

}  // namespace penumbra
