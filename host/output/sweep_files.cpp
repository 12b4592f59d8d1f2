#include "output/sweep_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>

#include "geometry/fnv1a_hash.hpp"
#include "output/result_files.hpp"
#include "output/staged_directory.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// StagedDirectory stages a missing target in `.<name>.partial-<pid>` beside it. A killed run
// leaves one behind; the next run of the same case clears it (only one process runs a case).
void removeLeftovers(const fs::path& folder) {
  const std::string prefix = fmt::format(".{}.partial-", folder.filename().string());
  std::error_code ec;
  if (!fs::is_directory(folder.parent_path(), ec)) return;
  for (const auto& entry : fs::directory_iterator(folder.parent_path(), ec)) {
    if (entry.path().filename().string().starts_with(prefix)) fs::remove_all(entry.path(), ec);
  }
}

// A whole folder at once: a stale one is removed first, so that the staged one is renamed into
// place in one step (a rename cannot replace a directory that has files).
void replaceFolder(const fs::path& folder, const std::function<void(const fs::path&)>& fill) {
  const fs::path target = normalizedTarget(folder);
  removeLeftovers(target);
  fs::remove_all(target);
  StagedDirectory staged(target);
  fill(staged.staging());
  staged.commit();
}

// Beside the charts: which data each PNG shows.
constexpr const char* kDrawnCharts = "charts.json";

std::string chartFingerprint(const LineChart& chart) {
  Fnv1a h;
  h.add(std::string_view("penumbra chart 1"));
  for (const std::string& text : {chart.title, chart.xLabel, chart.yLabel}) h.add(text);
  h.add(static_cast<double>(chart.width));
  h.add(static_cast<double>(chart.height));
  for (const ChartSeries& series : chart.series) {
    h.add(std::string_view(series.name));
    for (double x : series.x) h.add(x);
    h.add(std::string_view("y"));
    for (double y : series.y) h.add(y);
  }
  return h.hex();
}

// {} when there is no such file or it is not JSON: every chart is then drawn again.
nlohmann::json readDrawnCharts(const fs::path& file) {
  std::ifstream in(file);
  nlohmann::json drawn = nlohmann::json::parse(in, nullptr, false);
  return drawn.is_object() ? drawn : nlohmann::json::object();
}

}  // namespace

void writeCaseFolder(const fs::path& folder, const Scene& scene, const RunReport& report,
                     nlohmann::ordered_json caseJson,
                     const std::vector<CaseOutputWriter*>& outputs) {
  replaceFolder(folder, [&](const fs::path& staging) {
    writeResultFiles(report, staging);
    std::vector<std::string> images;
    for (CaseOutputWriter* writer : outputs) {
      for (std::string& image : writer->write(scene, report, staging)) {
        // One column per image name in results.csv: a second writer must not take it over.
        if (std::find(images.begin(), images.end(), image) != images.end()) {
          throw std::runtime_error(
              fmt::format("{}: the {} wrote {}, which another output wrote too", folder.string(),
                          writer->name(), image));
        }
        images.push_back(std::move(image));
      }
    }
    caseJson["images"] = images;
    // Last: a case folder with case.json is complete (and the rename makes it appear whole).
    writeFile(staging / "case.json", [&](std::ostream& out) { out << caseJson.dump(2) << "\n"; });
  });
}

void copyCaseFolder(const fs::path& from, const fs::path& to) {
  replaceFolder(to, [&](const fs::path& staging) {
    fs::copy(from, staging, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
  });
}

void writeTextFiles(const fs::path& out,
                    const std::vector<std::pair<std::string, std::string>>& files) {
  StagedDirectory staged(out);
  // Not a structured binding: clang 14 (the fuzz and sanitizer build) cannot capture one.
  for (const auto& file : files) {
    writeFile(staged.staging() / file.first, [&](std::ostream& stream) { stream << file.second; });
  }
  staged.commit();
}

ChartsWritten writeCharts(const fs::path& directory, const std::vector<ChartFile>& charts,
                          const ChartWriter& writer) {
  const nlohmann::json previous = readDrawnCharts(directory / kDrawnCharts);
  nlohmann::ordered_json drawn = nlohmann::ordered_json::object();
  std::vector<ChartFile> toDraw;
  ChartsWritten written;
  for (const ChartFile& c : charts) {
    const std::string fingerprint = chartFingerprint(c.chart);
    if (fs::exists(directory / c.fileName) && previous.value(c.fileName, "") == fingerprint) {
      drawn[c.fileName] = fingerprint;
      ++written.kept;
    } else {
      toDraw.push_back(c);
    }
  }
  StagedDirectory staged(directory);
  if (!toDraw.empty()) {
    try {
      writer.draw(toDraw, staged.staging());
    } catch (const std::exception& e) {
      written.why = e.what();
    }
  }
  for (const ChartFile& c : toDraw) {
    if (fs::exists(staged.staging() / c.fileName)) {
      drawn[c.fileName] = chartFingerprint(c.chart);
      ++written.drawn;
    } else {
      written.missing.push_back(c.fileName);
    }
  }
  if (!written.missing.empty() && written.why.empty()) written.why = "the chart writer wrote none";
  writeFile(staged.staging() / kDrawnCharts,
            [&](std::ostream& out) { out << drawn.dump(2) << "\n"; });
  staged.commit();
  return written;
}

}  // namespace penumbra
