#pragma once
// The table `penumbra grid` prints when it is done: one row per grid.
#include <string>

#include "grid/run_report.hpp"

namespace penumbra {

// Columns: Grid | Points | Spacing [m] | Eavg [lx] | Emin [lx] | Emax [lx] | U0 | Ud, then one note
// per grid with points inside solids (they are left out of the statistics). Ends with '\n'.
std::string summaryTable(const RunReport& report);

}  // namespace penumbra
