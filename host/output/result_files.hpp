#pragma once
// The files of a `penumbra grid` run, all in one output directory:
//   <grid>.csv     x_m,y_m,z_m,nx,ny,nz,E_lx,inside   one row per point, in the grid's order
//   <grid>.res     E in lx, one value a line, same order (what `rtrace -h -ov` gives Radiance
//                  users)
//   summary.json   scene, device, timing and the metrics of every grid, units in the key names
// Numbers are written in the shortest form that reads back to the same double, and E and the
// metrics of a kernel run in the shortest that reads back to the same float (grid_rows.hpp).
// A grid computed batch by batch goes to its files through GridFileWriter (grid_file_writer.hpp).
#include <filesystem>
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grid/grid_evaluation.hpp"
#include "grid/run_report.hpp"
#include "output/number_text.hpp"

namespace penumbra {

// The file name stem of a grid: its name with every character outside [A-Za-z0-9._-] replaced by
// '_' (grid names come from the scene; they must not reach outside the output directory).
std::string gridFileStem(const std::string& gridName);
// The same for any name; `prefix` goes in front of an empty name or one starting with '.'.
std::string safeFileStem(const std::string& name, const std::string& prefix);
// {"window_width_m": 1.6, ...}: the values the scene's parameters had in a run.
nlohmann::json parameterJson(const ParameterValues& values);

// The `kind` of a grid in summary.json: "work-plane", "rect" or "points". The reverse throws
// std::runtime_error for any other name.
std::string gridKindName(GridKind kind);
GridKind gridKindFromName(const std::string& name);

// The names of the files writeResults creates for `report` (or for grids of these names). Throws
// std::runtime_error when two grids would share a file.
std::vector<std::string> resultFileNames(const RunReport& report);
std::vector<std::string> resultFileNames(const std::vector<std::string>& gridNames);

// The digits E and its metrics hold in `report`: a float's for the kernel estimator (single
// precision on the device), a double's for the host reference.
NumberDigits illuminanceDigits(const RunReport& report);

// The metrics as the files give them: with the digits E holds, and U0 and Ud undefined (NaN) for
// a point list, whose scattered sensors make no area to be uniform over.
GridMetrics reportedMetrics(const GridMetrics& metrics, GridKind kind, NumberDigits digits);

// `digits`: those of E (illuminanceDigits).
void writeGridCsv(std::ostream& out, const GridReport& grid, NumberDigits digits);
void writeGridRes(std::ostream& out, const GridReport& grid, NumberDigits digits);
void writeGridPts(std::ostream& out, const GridReport& grid);
nlohmann::json summaryJson(const RunReport& report);
// What E includes, in words: "total (direct + interreflected)" or "direct only", followed by
// the luminaires' maintenance (maintenanceMeaning) where one has a factor below 1.
std::string illuminanceMeaning(const RunReport& report);
std::string illuminanceMeaning(bool interreflection,
                               const std::vector<LuminaireReport>& luminaires);
// The maintenance the luminaires' light includes: "" when every maintenance factor is 1 (or
// there are no luminaires), "maintained, MF 0.8" when all share one, otherwise "maintained (MF
// per luminaire: panel 0.8, downlight 0.9)".
std::string maintenanceMeaning(const std::vector<LuminaireReport>& luminaires);
// The interreflection solver's report and the photometric luminaires, as summary.json and
// render.json give them.
nlohmann::json interreflectionJson(const InterreflectionReport& report);
nlohmann::json luminairesJson(const std::vector<LuminaireReport>& luminaires);

// Writes summary.json (summaryJson) into `directory`.
void writeSummaryFile(const RunReport& report, const std::filesystem::path& directory);

// Writes every file of the run into the existing `directory`, as they are (a sweep's case folder
// is staged as a whole by its caller).
void writeResultFiles(const RunReport& report, const std::filesystem::path& directory);

// RFC 4180: a field with a comma, quote or line break is quoted, quotes doubled.
std::string csvField(const std::string& text);
// Creates `path` and writes it with `body`; throws std::runtime_error naming it on failure.
void writeFile(const std::filesystem::path& path, const std::function<void(std::ostream&)>& body);

// Writes every file of the run into `directory` atomically (see staged_directory.hpp): either all
// of them appear, or none does. Throws std::runtime_error or std::filesystem::filesystem_error.
void writeResults(const RunReport& report, const std::filesystem::path& directory);

}  // namespace penumbra
