#pragma once
// No partial output: files are written into a staging directory and moved into place only when
// all of them are complete.
//
//  * The target does not exist: staging is a hidden sibling (`<parent>/.<name>.partial-<pid>`, so
//    on the same file system) renamed to the target in one step.
//  * The target is an existing directory: staging is a hidden directory inside it, and each file
//    is renamed over its namesake (one atomic step per file). Files penumbra did not write in
//    this run (notes, results of grids not asked for this time) are left alone.
//
// A staging directory that is not committed is removed with everything in it, and so are the
// parent directories this object created.
#include <filesystem>
#include <vector>

namespace penumbra {

class StagedDirectory {
 public:
  // Throws std::runtime_error when the target exists and is not a directory.
  explicit StagedDirectory(const std::filesystem::path& target);
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  const std::filesystem::path& staging() const { return staging_; }
  const std::filesystem::path& target() const { return target_; }
  // Moves every file written under staging() into the target.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  std::vector<std::filesystem::path> createdParents_;  // deepest last
  bool targetExisted_ = false;
  bool committed_ = false;
};

// The target as an absolute path without a trailing separator ("out/office/" → /…/out/office).
std::filesystem::path normalizedTarget(const std::filesystem::path& target);

// Throws std::runtime_error (naming the path) when `target` cannot become an output directory;
// called before a long computation so that a typo fails fast.
void checkOutputTarget(const std::filesystem::path& target);

}  // namespace penumbra
