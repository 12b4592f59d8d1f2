#pragma once
// The UGR table of `penumbra luminaire FILE --ugr-table` (docs/glare.md, "The UGR table of a
// luminaire"): printed in the layout DIALux shows (rooms down, the five reflectance sets viewed
// crosswise then endwise across) and written as CSV, one row per spacing and room.
#include <filesystem>
#include <string>
#include <vector>

#include "glare/ugr_table.hpp"

namespace penumbra {

// The method in one line, as the printed table's header gives it.
std::string ugrTableMethod();

// One table as text, ending with '\n'.
std::string ugrTableText(const UgrTable& table);

// The tables into `path`: columns S_over_H, X_H, Y_H, X_m, Y_m, luminaires, then UGR per view
// and reflectance set (UGR_crosswise_70_50_20 ...), then L_b per reflectance set (cd/m²).
void writeUgrTableCsv(const std::vector<UgrTable>& tables, const std::filesystem::path& path);

}  // namespace penumbra
