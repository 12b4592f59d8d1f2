#pragma once
// Reads back what writeResults (result_files.hpp) writes: summary.json and every grid's CSV, into
// the RunReport they were written from. For `penumbra plot`, which works on a finished run.
#include <filesystem>

#include <istream>
#include <nlohmann/json.hpp>
#include <string>

#include "grid/run_report.hpp"

namespace penumbra {

// The run in `directory`. The scene file is the absolute path summary.json recorded when it has
// one, else the path as given on the command line; the parameters are the values the run used
// (load the scene with them to see what was computed). Metrics are recomputed from the CSV (points
// inside solids left out, as the run did). Throws std::runtime_error naming the file, and the
// line for CSV, when a file is missing or malformed.
RunReport readResults(const std::filesystem::path& directory);

// `file` (a run's summary.json) parsed; throws std::runtime_error naming it when it is missing or
// is not JSON.
nlohmann::json readSummary(const std::filesystem::path& file);

// The rows of one grid's CSV into `grid.points` (solid -1: the CSV does not say which surface a
// point lies on), `grid.insideSolids` and `grid.illuminance`. `fileName` is for messages.
void readGridCsv(std::istream& in, const std::string& fileName, GridReport& grid);

}  // namespace penumbra
