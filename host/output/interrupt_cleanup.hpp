#pragma once
// A run stopped by SIGINT (Ctrl-C) or SIGTERM (a cluster's time limit, `kill`) leaves no staging
// directory behind. Final names are safe without this (StagedDirectory renames only
// complete files into place); this removes the hidden `.partial-<pid>` leftovers too.
//
// Cleaning up inside a signal handler is not allowed (no allocation, no locks, no filesystem
// library), so the signals are blocked in every thread and one thread waits for them with
// sigwait(): it takes the registry's lock (never in the middle of a commit), removes every
// registered staging directory, and ends the process by the same signal. A child process started
// by penumbra inherits the blocked mask: give it an unblocked one (posix_spawnattr_setsigmask).
#include <filesystem>
#include <vector>

namespace penumbra {

// Call first thing in main(), before any thread starts (PoCL and TBB threads inherit the blocked
// signal mask). Safe to call more than once.
void removeStagingOnInterrupt();

// Held by StagedDirectory for its staging directory's lifetime; no-ops when
// removeStagingOnInterrupt() was never called (tests, libraries). `createdParents` (outermost
// first) are the folders the run creates to hold the staging directory: an interrupt removes
// them too, innermost first, each only if empty, so `-o new/out` stopped leaves no `new/`.
void registerStaging(const std::filesystem::path& staging,
                     const std::vector<std::filesystem::path>& createdParents = {});
void unregisterStaging(const std::filesystem::path& staging);

// While one exists, an interrupt waits (a commit renaming files into place is finished first).
class InterruptDeferral {
 public:
  InterruptDeferral();
  ~InterruptDeferral();
  InterruptDeferral(const InterruptDeferral&) = delete;
  InterruptDeferral& operator=(const InterruptDeferral&) = delete;
};

}  // namespace penumbra
