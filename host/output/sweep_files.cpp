#include "output/sweep_files.hpp"

#include <fmt/format.h>

#include <algorithm>
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
  std::vector<PictureFile> pictures;
  for (const ChartFile& c : charts) pictures.push_back({c.fileName, chartFingerprint(c.chart)});
  return writePictures(directory, kDrawnCharts, pictures,
                       [&](const std::vector<std::string>& names, const fs::path& staging) {
                         std::vector<ChartFile> toDraw;
                         for (const ChartFile& c : charts) {
                           if (std::find(names.begin(), names.end(), c.fileName) != names.end()) {
                             toDraw.push_back(c);
                           }
                         }
                         writer.draw(toDraw, staging);
                       });
}

}  // namespace penumbra
