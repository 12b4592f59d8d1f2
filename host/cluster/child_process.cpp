#include "cluster/child_process.hpp"

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>

namespace penumbra {
namespace {

// The child: runs the work, sends its error message (if any) through `pipeOut`, never returns.
[[noreturn]] void runChild(const std::function<void()>& work, int pipeOut) {
  int status = 0;
  std::string message;
  try {
    work();
  } catch (const std::exception& e) {
    message = e.what();
    status = 1;
  } catch (...) {
    message = "unknown error";
    status = 1;
  }
  for (std::size_t sent = 0; sent < message.size();) {
    const ssize_t n = ::write(pipeOut, message.data() + sent, message.size() - sent);
    if (n <= 0) break;
    sent += static_cast<std::size_t>(n);
  }
  ::close(pipeOut);
  std::fflush(nullptr);
  _exit(status);  // no atexit handlers and no static destructors: they belong to the parent
}

std::string readAll(int pipeIn) {
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(pipeIn, buffer, sizeof buffer);
    if (n > 0) {
      text.append(buffer, static_cast<std::size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      break;
    }
  }
  return text;
}

}  // namespace

void runInChildProcess(const std::function<void()>& work) {
  int pipeEnds[2];
  if (::pipe(pipeEnds) != 0) {
    throw std::runtime_error(fmt::format("cannot create a pipe: {}", std::strerror(errno)));
  }
  std::fflush(nullptr);  // what the parent buffered is printed once, not by both
  const pid_t child = ::fork();
  if (child < 0) {
    const int error = errno;
    ::close(pipeEnds[0]);
    ::close(pipeEnds[1]);
    throw std::runtime_error(fmt::format("cannot start a process: {}", std::strerror(error)));
  }
  if (child == 0) {
    ::close(pipeEnds[0]);
    runChild(work, pipeEnds[1]);
  }
  ::close(pipeEnds[1]);
  const std::string message = readAll(pipeEnds[0]);
  ::close(pipeEnds[0]);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) {
      throw std::runtime_error(fmt::format("lost the child process: {}", std::strerror(errno)));
    }
  }
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    throw std::runtime_error(
        fmt::format("the child process was killed by signal {} ({})", signal, ::strsignal(signal)));
  }
  if (WEXITSTATUS(status) != 0) {
    throw std::runtime_error(
        message.empty() ? fmt::format("the child process ended with status {}", WEXITSTATUS(status))
                        : message);
  }
}

}  // namespace penumbra
