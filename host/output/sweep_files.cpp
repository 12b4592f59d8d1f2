#include "output/sweep_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <system_error>

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

void writeCharts(const fs::path& directory, const std::vector<ChartFile>& charts,
                 const ChartWriter& writer) {
  StagedDirectory staged(directory);
  for (const ChartFile& c : charts) writer(c.chart, staged.staging() / c.fileName);
  staged.commit();
}

}  // namespace penumbra
