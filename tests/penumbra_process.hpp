#pragma once
// The `penumbra` binary as a user runs it, for the tests of the command line: run to the end, or
// start in the background and stop it midway (a kill, as a user's Ctrl-C or a cluster's timeout).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "test_files.hpp"

namespace penumbra::testing {

struct Result {
  int status = -1;
  std::string out, err;
};

// Runs penumbra with `arguments` (already shell-quoted) in `dir`.
inline Result runPenumbra(const std::filesystem::path& dir, const std::string& arguments) {
  const std::string command = "cd '" + dir.string() + "' && '" PENUMBRA_BINARY "' " + arguments +
                              " > stdout.txt 2> stderr.txt < /dev/null";
  const int raw = std::system(command.c_str());
  Result r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = readText(dir / "stdout.txt");
  r.err = readText(dir / "stderr.txt");
  std::filesystem::remove(dir / "stdout.txt");
  std::filesystem::remove(dir / "stderr.txt");
  return r;
}

// penumbra started in the background with `arguments` (one word each), working in `dir`, its
// output discarded. The destructor kills it if it still runs.
class PenumbraProcess {
 public:
  PenumbraProcess(const std::filesystem::path& dir, std::vector<std::string> arguments) {
    arguments.insert(arguments.begin(), PENUMBRA_BINARY);
    std::vector<char*> argv;
    for (std::string& a : arguments) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
    const std::filesystem::path previous = std::filesystem::current_path();
    std::filesystem::current_path(dir);  // the child inherits it
    if (posix_spawn(&pid_, PENUMBRA_BINARY, &actions, nullptr, argv.data(), environ) != 0)
      pid_ = -1;
    std::filesystem::current_path(previous);
    posix_spawn_file_actions_destroy(&actions);
  }
  ~PenumbraProcess() {
    if (running()) kill();
  }
  PenumbraProcess(const PenumbraProcess&) = delete;
  PenumbraProcess& operator=(const PenumbraProcess&) = delete;

  bool started() const { return pid_ > 0; }
  // Whether it still runs (reaps it when it has ended).
  bool running() {
    if (pid_ <= 0 || exited_) return false;
    int status = 0;
    exited_ = ::waitpid(pid_, &status, WNOHANG) == pid_;
    return !exited_;
  }
  // SIGKILL: no chance to clean up, the hardest way a run can stop.
  void kill() { stop(SIGKILL); }
  // Sends `signal` (SIGINT as Ctrl-C, SIGTERM as a scheduler's limit) and waits for the end;
  // returns the wait status (WIFSIGNALED, WTERMSIG, ...).
  int stop(int signal) {
    ::kill(pid_, signal);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    exited_ = true;
    return status;
  }
  pid_t pid() const { return pid_; }

 private:
  pid_t pid_ = -1;
  bool exited_ = false;
};

}  // namespace penumbra::testing
