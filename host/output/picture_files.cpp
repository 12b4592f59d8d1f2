#include "output/picture_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <exception>
#include <fstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "cluster/child_process.hpp"
#include "output/result_files.hpp"
#include "output/staged_directory.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// {} when there is no such file or it is not JSON: every picture is then drawn again.
nlohmann::json readRecord(const fs::path& file) {
  std::ifstream in(file);
  nlohmann::json record = nlohmann::json::parse(in, nullptr, false);
  return record.is_object() ? record : nlohmann::json::object();
}

}  // namespace

PicturesWritten writePictures(const fs::path& directory, const std::string& recordName,
                              const std::vector<PictureFile>& pictures,
                              const PictureDrawing& draw) {
  const nlohmann::json previous = readRecord(directory / recordName);
  // Pictures of this record not asked for this time (a grid left out of a rerun) stay listed.
  nlohmann::ordered_json record = nlohmann::ordered_json::object();
  for (auto it = previous.begin(); it != previous.end(); ++it) {
    if (it->is_string() && fs::exists(directory / it.key())) record[it.key()] = *it;
  }
  std::vector<std::string> toDraw;
  PicturesWritten written;
  for (const PictureFile& p : pictures) {
    if (fs::exists(directory / p.fileName) && previous.value(p.fileName, "") == p.fingerprint) {
      ++written.kept;
    } else {
      record.erase(p.fileName);
      toDraw.push_back(p.fileName);
    }
  }
  StagedDirectory staged(directory);
  // A drawing that fails is tried once more for the pictures it left: a display that refused
  // one connection (an X server busy starting others) usually takes the next.
  std::vector<std::string> remaining = toDraw;
  for (int attempt = 0; attempt < 2 && !remaining.empty(); ++attempt) {
    try {
      draw(remaining, staged.staging());
      written.why.clear();
    } catch (const std::exception& e) {
      written.why = e.what();
    }
    if (written.why.empty()) break;
    std::erase_if(remaining,
                  [&](const std::string& name) { return fs::exists(staged.staging() / name); });
  }
  for (const PictureFile& p : pictures) {
    if (std::find(toDraw.begin(), toDraw.end(), p.fileName) == toDraw.end()) continue;
    if (fs::exists(staged.staging() / p.fileName)) {
      record[p.fileName] = p.fingerprint;
      ++written.drawn;
    } else {
      written.missing.push_back(p.fileName);
    }
  }
  if (!written.missing.empty() && written.why.empty()) written.why = "the drawing wrote none";
  writeFile(staged.staging() / recordName,
            [&](std::ostream& out) { out << record.dump(2) << "\n"; });
  staged.commit();
  return written;
}

PictureDrawing inChildProcess(PictureDrawing draw) {
  return [draw = std::move(draw)](const std::vector<std::string>& fileNames,
                                  const fs::path& directory) {
    runInChildProcess([&] { draw(fileNames, directory); });
  };
}

std::string missingPictures(const PicturesWritten& written, const std::string& noun) {
  if (written.missing.empty()) return "";
  std::string names;
  for (const std::string& name : written.missing) names += (names.empty() ? "" : ", ") + name;
  return fmt::format("{} {}{} not drawn ({}): {}", written.missing.size(), noun,
                     written.missing.size() == 1 ? "" : "s", names, written.why);
}

}  // namespace penumbra
