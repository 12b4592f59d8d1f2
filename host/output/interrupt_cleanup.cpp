#include "output/interrupt_cleanup.hpp"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace penumbra {

namespace {

// A recursive mutex: a commit (which holds it) unregisters its own staging directory.
std::recursive_mutex& registryMutex() {
  static std::recursive_mutex mutex;
  return mutex;
}

// A registered staging directory and the folders its run created to hold it, outermost first.
struct Staging {
  std::filesystem::path path;
  std::vector<std::filesystem::path> createdParents;
};

std::vector<Staging>& registry() {
  static std::vector<Staging> entries;
  return entries;
}

sigset_t interruptSignals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

[[noreturn]] void waitForInterrupt() {
  const sigset_t set = interruptSignals();
  int signal = SIGTERM;
  while (sigwait(&set, &signal) != 0) {
  }
  {
    // Taken and kept: no commit can start after this point, one in progress is finished.
    registryMutex().lock();
    // The writers go on while this runs: a file created in the staging directory after
    // remove_all listed it makes the directory's own removal fail ("not empty"); one pass alone
    // leaves the staging directory behind in about one run in a hundred under load (the Interrupt
    // tests under ctest -j4). Once the directory is gone no writer can recreate it (only
    // StagedDirectory's constructor creates it, after registering, which this lock blocks), so a
    // few passes do.
    std::error_code ec;
    for (const Staging& staging : registry()) {
      for (int pass = 0; pass < 100 && std::filesystem::exists(staging.path, ec); ++pass)
        std::filesystem::remove_all(staging.path, ec);
      // Then the folders the run created for it, innermost first, each only if now empty.
      for (auto it = staging.createdParents.rbegin(); it != staging.createdParents.rend(); ++it)
        std::filesystem::remove(*it, ec);
    }
  }
  // End the way the signal would have ended it, so that a shell or a scheduler sees the cause.
  ::signal(signal, SIG_DFL);
  pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  ::raise(signal);
  ::_exit(128 + signal);  // not reached
}

}  // namespace

void removeStagingOnInterrupt() {
  static std::once_flag started;
  std::call_once(started, [] {
    const sigset_t set = interruptSignals();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::thread(waitForInterrupt).detach();
  });
}

void registerStaging(const std::filesystem::path& staging,
                     const std::vector<std::filesystem::path>& createdParents) {
  std::lock_guard lock(registryMutex());
  registry().push_back({staging, createdParents});
}

void unregisterStaging(const std::filesystem::path& staging) {
  std::lock_guard lock(registryMutex());
  auto& entries = registry();
  const auto it = std::find_if(entries.begin(), entries.end(),
                               [&](const Staging& entry) { return entry.path == staging; });
  if (it != entries.end()) entries.erase(it);
}

InterruptDeferral::InterruptDeferral() {
  registryMutex().lock();
}
InterruptDeferral::~InterruptDeferral() {
  registryMutex().unlock();
}

}  // namespace penumbra
