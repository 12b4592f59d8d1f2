#pragma once
// What a sweep's output folder records about its study (OUT/study.json) and each finished case
// (OUT/cases/<id>/case.json): enough to rebuild the tables and charts, resume, and merge shard
// folders, without the study file.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "grid/grid_metrics.hpp"
#include "scene/parameters.hpp"
#include "study/study.hpp"

namespace penumbra {

struct PlannedCase {
  std::string id;
  ParameterValues values;
  std::string fingerprint;  // case_fingerprint.hpp
};

struct StudyLayout {
  std::string studyFile;  // as given, for people
  std::string sceneFile;
  std::vector<std::string> parameters;  // the study's, in its order
  Combination combination = Combination::Grid;
  std::vector<std::string> grids;  // computed per case, scene order
  std::vector<StudyMetric> metrics;
  std::vector<std::string> caseOutputs;  // per-case outputs asked for and written ("plots")
  bool charts = true;
  std::vector<PlannedCase> cases;

  // The same cases with the same fingerprints and outputs (file names may differ: shards can be
  // started from different folders).
  bool sameStudy(const StudyLayout& other) const;
};

struct CaseGridResult : CaseGridFigures {
  std::string name;
};

// A finished case, as its case.json says.
struct CaseRecord {
  std::string id;
  std::string fingerprint;
  ParameterValues values;
  std::vector<CaseGridResult> grids;
  std::vector<std::string> images;  // relative to the case folder
  // For a scene with observers: the largest UGR over its observers and lines of sight (nothing
  // when none has one, docs/glare.md); `rated` false for a scene without observers.
  bool rated = false;
  std::optional<double> ugrMax;
};

nlohmann::ordered_json layoutJson(const StudyLayout& layout);
// Throws std::runtime_error naming `file` when the JSON is not a study layout.
StudyLayout layoutFromJson(const nlohmann::ordered_json& json, const std::filesystem::path& file);

nlohmann::ordered_json caseJson(const CaseRecord& record);
CaseRecord caseRecordFromJson(const nlohmann::ordered_json& json,
                              const std::filesystem::path& file);

// The file names inside an output folder.
inline constexpr const char* kStudyJson = "study.json";
inline constexpr const char* kCasesFolder = "cases";
inline constexpr const char* kCaseJson = "case.json";

// OUT/study.json; nothing when the folder holds none. Throws std::runtime_error when it is
// unreadable or malformed.
std::optional<StudyLayout> readLayout(const std::filesystem::path& out);
// OUT/cases/<id>/case.json when the case is finished with `fingerprint`; nothing otherwise (a
// missing, unreadable or stale record means the case is computed again).
std::optional<CaseRecord> readFinishedCase(const std::filesystem::path& out,
                                           const PlannedCase& planned);

}  // namespace penumbra
