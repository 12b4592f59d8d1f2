#pragma once
// A grid's results as a VTK XML file for ParaView: a planar grid as image data (.vti, the
// lattice with its orientation), a point list as poly data (.vtp, one vertex per point). Point
// arrays: "E_lx" (the CSV's values, as doubles, so bit for bit), "Normals" and "inside_solid"
// (1 where the point is inside a solid and E is 0 by convention).
#include <filesystem>
#include <string>

#include "grid/run_report.hpp"

namespace penumbra::viz {

// "<stem>.vti" or "<stem>.vtp".
std::string gridDatasetFileName(const GridReport& grid);

// Needs no display. Throws std::runtime_error when the file cannot be written, and
// std::invalid_argument when a planar grid's points are not a lattice.
void writeGridDataset(const GridReport& grid, const std::filesystem::path& file);

}  // namespace penumbra::viz
