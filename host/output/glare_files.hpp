#pragma once
// The files and the table of `penumbra glare` (docs/glare.md, "Output"): per `observers:` entry
// a CSV of ratings (one row per eye and line of sight) and a CSV of the glare sources behind
// each rating; summary.json with the method and every rating; the table printed at the end.
#include <filesystem>
#include <string>
#include <vector>

#include "glare/observer_ratings.hpp"

namespace penumbra {

// What a glare run was, for summary.json and the table's header.
struct GlareRun {
  std::filesystem::path sceneFile;
  std::string version;
  std::string device;           // in words
  bool interreflection = true;  // false: L_b = 0, every UGR undefined
  std::vector<ObserverRating> ratings;
  double seconds = 0.0;
};

// The method in one line, as every header gives it.
std::string glareMethod();
// Why a view has no UGR ("L_b = 0 ...", "no glare source ..."); empty when it has one.
std::string undefinedReason(const GlareRating& rating, bool interreflection);

// <entry>.csv and <entry>-sources.csv per observers: entry, and summary.json, into `directory`.
// Throws std::runtime_error when two entries would share a file.
void writeGlareFiles(const GlareRun& run, const std::filesystem::path& directory);

// One row per observer: UGR along each line of sight, UGR_max, the limit it meets, the strongest
// source. Ends with '\n'.
std::string glareTable(const GlareRun& run);

}  // namespace penumbra
