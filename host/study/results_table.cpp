#include "study/results_table.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "output/result_files.hpp"

namespace penumbra {
namespace {

std::string csvNumber(double value) {
  return std::isfinite(value) ? fmt::format("{}", value) : std::string();
}

// Images in the order they first appear; a case without one gets an empty field.
std::vector<std::string> imageNames(const std::vector<CaseRecord>& records) {
  std::vector<std::string> names;
  for (const CaseRecord& r : records) {
    for (const std::string& image : r.images) {
      if (std::find(names.begin(), names.end(), image) == names.end()) names.push_back(image);
    }
  }
  return names;
}

std::string imageColumn(const std::string& image) {
  const std::filesystem::path path(image);
  std::string stem = path.stem().string();
  std::string type = path.extension().string();
  if (!type.empty()) type.erase(0, 1);
  return type.empty() ? stem : stem + "_" + type;
}

const CaseGridResult* gridOf(const CaseRecord& record, const std::string& name) {
  for (const CaseGridResult& g : record.grids) {
    if (g.name == name) return &g;
  }
  return nullptr;
}

// The same cells for both tables; `prefix` decorates each group's header.
struct Prefixes {
  bool withId = true;
  std::string parameter, metric, image;
};

Table buildTable(const StudyLayout& layout, const std::vector<CaseRecord>& records,
                 const Prefixes& prefix) {
  const std::vector<std::string> images = imageNames(records);
  Table table;
  if (prefix.withId) table.header.push_back("case_id");
  for (const std::string& p : layout.parameters) table.header.push_back(prefix.parameter + p);
  for (const std::string& grid : layout.grids) {
    for (StudyMetric m : layout.metrics) {
      table.header.push_back(prefix.metric + metricColumn(layout, m, grid));
    }
  }
  const bool rated =
      std::any_of(records.begin(), records.end(), [](const CaseRecord& r) { return r.rated; });
  if (rated) table.header.push_back(prefix.metric + kUgrMaxColumn);
  for (const std::string& image : images) table.header.push_back(prefix.image + imageColumn(image));

  for (const CaseRecord& r : records) {
    std::vector<std::string> row;
    if (prefix.withId) row.push_back(r.id);
    for (const std::string& name : layout.parameters) {
      const auto it = std::find_if(r.values.begin(), r.values.end(),
                                   [&](const ParameterValue& p) { return p.name == name; });
      row.push_back(it == r.values.end() ? std::string() : csvNumber(it->value));
    }
    for (const std::string& grid : layout.grids) {
      const CaseGridResult* result = gridOf(r, grid);
      for (StudyMetric m : layout.metrics) {
        row.push_back(result != nullptr ? csvNumber(metricValue(*result, m)) : std::string());
      }
    }
    if (rated) row.push_back(r.ugrMax ? csvNumber(*r.ugrMax) : std::string());
    for (const std::string& image : images) {
      const bool has = std::find(r.images.begin(), r.images.end(), image) != r.images.end();
      row.push_back(has ? (std::filesystem::path(kCasesFolder) / r.id / image).generic_string()
                        : std::string());
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace

std::string metricColumn(const StudyLayout& layout, StudyMetric metric, const std::string& grid) {
  const std::string column(metricInfo(metric).column);
  return layout.grids.size() > 1 ? column + "@" + grid : column;
}

Table resultsTable(const StudyLayout& layout, const std::vector<CaseRecord>& records) {
  return buildTable(layout, records, Prefixes{true, "", "", ""});
}

Table designExplorerTable(const StudyLayout& layout, const std::vector<CaseRecord>& records) {
  return buildTable(layout, records, Prefixes{false, "in:", "out:", "img:"});
}

std::string csvText(const Table& table) {
  const auto line = [](const std::vector<std::string>& cells) {
    std::string text;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (i > 0) text += ',';
      text += csvField(cells[i]);
    }
    return text + "\n";
  };
  std::string text = line(table.header);
  for (const auto& row : table.rows) text += line(row);
  return text;
}

}  // namespace penumbra
