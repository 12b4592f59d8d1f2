#include "cli/render_progress.hpp"
#include "timing/seconds_since.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace penumbra {

RenderProgress::RenderProgress(bool enabled, std::string view, int rows)
    : enabled_(enabled),
      terminal_(enabled && ::isatty(STDERR_FILENO) != 0),
      view_(std::move(view)),
      rows_(rows),
      start_(std::chrono::steady_clock::now()) {}

void RenderProgress::update(double fraction) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < 1.0) return;
  // Off a terminal, one line a second at most, so that logs stay short.
  const auto every = terminal_ ? std::chrono::milliseconds(100) : std::chrono::milliseconds(1000);
  if (shown_ && now - lastPrint_ < every) return;
  lastPrint_ = now;
  shown_ = true;
  const int rows = static_cast<int>(std::floor(fraction * rows_));
  const std::string eta = fraction > 0.0
                              ? fmt::format("{:.1f} s left", elapsed * (1.0 / fraction - 1.0))
                              : std::string("estimating");
  fmt::print(stderr, "{}penumbra: view {}: rows {}/{} ({:.0f}%), {}{}", terminal_ ? "\r" : "",
             view_, rows, rows_, 100.0 * fraction, eta, terminal_ ? "\033[K" : "\n");
  std::fflush(stderr);
}

void RenderProgress::finish() {
  if (!enabled_) return;
  if (terminal_ && shown_) fmt::print(stderr, "\r\033[K");
  const double elapsed = secondsSince(start_);
  fmt::print(stderr, "penumbra: view {}: done in {:.2f} s\n", view_, elapsed);
}

}  // namespace penumbra
