#pragma once
// The tables of a sweep, built from the finished cases' records:
//  results.csv          case_id, every parameter, every metric with its unit in the header
//                       (Eavg_lx, ..., U0, Ud; "Eavg_lx@<grid>" when the study has several
//                       grids), UGR_max when the scene has observers (CIE 117 UGR, the
//                       largest over its observers and lines of sight, L_b from the
//                       interreflection: docs/glare.md), and the relative path of each case
//                       image ("<image>_png")
//  design-explorer.csv  the same as in:<parameter>, out:<metric>, img:<image> columns, the form
//                       Design Explorer (and similar tools) read
#include <string>
#include <vector>

#include "study/study_layout.hpp"

namespace penumbra {

// The column of the largest UGR of a case whose scene has observers.
inline constexpr const char* kUgrMaxColumn = "UGR_max";

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

// One row per record, in the order given (case order). Numbers in the shortest form that reads
// back to the same double; an undefined metric (U0 with Eavg = 0) is an empty field.
Table resultsTable(const StudyLayout& layout, const std::vector<CaseRecord>& records);
Table designExplorerTable(const StudyLayout& layout, const std::vector<CaseRecord>& records);

// RFC 4180 text, one line per row, '\n' line ends.
std::string csvText(const Table& table);

// The header of a metric's column: "Eavg_lx", or "Eavg_lx@work-plane" when the study has several
// grids. Charts use the same words.
std::string metricColumn(const StudyLayout& layout, StudyMetric metric, const std::string& grid);

}  // namespace penumbra
