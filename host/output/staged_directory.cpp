#include "output/staged_directory.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <stdexcept>
#include <string>
#include <system_error>

#include "output/interrupt_cleanup.hpp"

namespace penumbra {

namespace fs = std::filesystem;

fs::path normalizedTarget(const fs::path& target) {
  if (target.empty()) throw std::runtime_error("the output directory name is empty");
  fs::path p = fs::absolute(target).lexically_normal();
  while (!p.has_filename() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
  return p;
}

void checkOutputTarget(const fs::path& target) {
  const fs::path p = normalizedTarget(target);
  std::error_code ec;
  if (fs::exists(p, ec) && !fs::is_directory(p, ec)) {
    throw std::runtime_error("output path " + p.string() + " exists and is not a directory");
  }
  // The nearest existing ancestor must be a directory, or nothing can be created under it.
  for (fs::path a = p.parent_path(); !a.empty(); a = a.parent_path()) {
    if (fs::exists(a, ec)) {
      if (!fs::is_directory(a, ec)) {
        throw std::runtime_error("cannot create output directory " + p.string() + ": " +
                                 a.string() + " is not a directory");
      }
      break;
    }
    if (a == a.root_path()) break;
  }
}

StagedDirectory::StagedDirectory(const fs::path& target) : target_(normalizedTarget(target)) {
  checkOutputTarget(target_);
  targetExisted_ = fs::is_directory(target_);
  const int pid = static_cast<int>(::getpid());
  if (targetExisted_) {
    staging_ = target_ / fmt::format(".penumbra.partial-{}", pid);
  } else {
    // Remember which ancestors are new, so that a failed or interrupted run leaves nothing
    // behind.
    std::vector<fs::path> missing;
    for (fs::path a = target_.parent_path(); !fs::exists(a); a = a.parent_path()) {
      missing.push_back(a);
      if (a == a.root_path()) break;
    }
    createdParents_.assign(missing.rbegin(), missing.rend());
    staging_ =
        target_.parent_path() / fmt::format(".{}.partial-{}", target_.filename().string(), pid);
  }
  // Before anything is created: an interrupt from here on removes the staging directory and the
  // parents created for it.
  registerStaging(staging_, createdParents_);
  try {
    for (const fs::path& parent : createdParents_) fs::create_directory(parent);
    fs::remove_all(staging_);  // a leftover of a killed run with the same pid
    fs::create_directory(staging_);
  } catch (...) {
    std::error_code ec;
    for (auto it = createdParents_.rbegin(); it != createdParents_.rend(); ++it)
      fs::remove(*it, ec);  // only if empty
    unregisterStaging(staging_);
    throw;
  }
}

StagedDirectory::~StagedDirectory() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
  for (auto it = createdParents_.rbegin(); it != createdParents_.rend(); ++it) {
    fs::remove(*it, ec);  // only if still empty
  }
  unregisterStaging(staging_);
}

void StagedDirectory::commit() {
  if (committed_) throw std::logic_error("StagedDirectory committed twice");
  const InterruptDeferral deferral;  // SIGINT/SIGTERM wait until every file is in place
  if (!targetExisted_ && !fs::exists(target_)) {
    fs::rename(staging_, target_);
  } else {
    fs::create_directories(target_);
    for (const auto& entry : fs::directory_iterator(staging_)) {
      fs::rename(entry.path(), target_ / entry.path().filename());
    }
    fs::remove(staging_);
  }
  committed_ = true;
  unregisterStaging(staging_);
}

}  // namespace penumbra
