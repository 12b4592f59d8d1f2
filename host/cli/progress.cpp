#include "cli/progress.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace penumbra {

ProgressLine::ProgressLine(bool enabled)
    : enabled_(enabled), terminal_(enabled && ::isatty(STDERR_FILENO) != 0) {}

void ProgressLine::startGrid(const std::string& name, std::size_t points) {
  grid_ = name;
  total_ = points;
  if (!enabled_) return;
  if (terminal_) {
    update(0, points);
  } else {
    fmt::print(stderr, "penumbra: grid {}: {} points...\n", name, points);
  }
}

void ProgressLine::update(std::size_t done, std::size_t total) {
  if (!terminal_) return;
  const auto now = std::chrono::steady_clock::now();
  if (done < total && now - lastPrint_ < std::chrono::milliseconds(100)) return;
  lastPrint_ = now;
  const double percent = total > 0 ? 100.0 * static_cast<double>(done) / total : 100.0;
  fmt::print(stderr, "\rpenumbra: grid {}: {}/{} points ({:.0f}%)", grid_, done, total, percent);
  std::fflush(stderr);
}

void ProgressLine::finishGrid(double seconds) {
  if (!enabled_) return;
  if (terminal_) fmt::print(stderr, "\r\033[K");  // clear the in-place line
  fmt::print(stderr, "penumbra: grid {}: {}/{} points done in {:.2f} s\n", grid_, total_, total_,
             seconds);
}

}  // namespace penumbra
