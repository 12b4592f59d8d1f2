#include "cli/sweep_progress.hpp"
#include "timing/seconds_since.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace penumbra {
namespace {

std::string duration(double seconds) {
  if (seconds < 60.0) return fmt::format("{:.0f} s", std::ceil(seconds));
  if (seconds < 3600.0)
    return fmt::format("{:.0f} min {:02.0f} s", std::floor(seconds / 60.0),
                       std::fmod(seconds, 60.0));
  return fmt::format("{:.0f} h {:02.0f} min", std::floor(seconds / 3600.0),
                     std::fmod(seconds / 60.0, 60.0));
}

// The first grid's Eavg and U0: what a designer looks at first.
std::string headline(const CaseRecord& record) {
  if (record.grids.empty()) return "no grids";
  const CaseGridResult& g = record.grids.front();
  return fmt::format("{}: Eavg {:.1f} lx, U0 {:.3f}", g.name, g.metrics.eAvg, g.metrics.u0);
}

}  // namespace

SweepProgress::SweepProgress(bool enabled)
    : enabled_(enabled), terminal_(enabled && ::isatty(STDERR_FILENO) != 0) {}

void SweepProgress::planned(std::size_t toCompute, std::size_t finished) {
  total_ = toCompute;
  start_ = std::chrono::steady_clock::now();
  if (!enabled_) return;
  if (finished > 0) {
    fmt::print(stderr, "penumbra: {} case{} already finished (skipped)\n", finished,
               finished == 1 ? "" : "s");
  }
  fmt::print(stderr, "penumbra: {} case{} to compute\n", toCompute, toCompute == 1 ? "" : "s");
}

double SweepProgress::etaSeconds() const {
  const double elapsed = secondsSince(start_);
  return done_ > 0 ? elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_)
                   : 0.0;
}

void SweepProgress::drawBar(const std::string& current) const {
  constexpr int kWidth = 24;
  const int filled = total_ > 0 ? static_cast<int>(kWidth * done_ / total_) : kWidth;
  const std::string eta = done_ > 0 ? " · ETA " + duration(etaSeconds()) : "";
  fmt::print(stderr, "\r\033[Kpenumbra: [{}{}] {}/{} cases{} · {}", std::string(filled, '#'),
             std::string(kWidth - filled, '.'), done_, total_, eta, current);
  std::fflush(stderr);
}

void SweepProgress::caseStarted(const PlannedCase& c) {
  // The id only: a line longer than the terminal wraps, and a wrapped line cannot be redrawn.
  if (terminal_) drawBar(c.id);
}

void SweepProgress::caseFinished(const CaseRecord& record, double seconds) {
  ++done_;
  if (!enabled_) return;
  if (terminal_) {
    fmt::print(stderr, "\r\033[K");
    if (done_ == total_) fmt::print(stderr, "penumbra: {} cases computed\n", total_);
    return;
  }
  fmt::print(stderr, "penumbra: {} ({}/{}, {}) {} · {:.2f} s{}\n", record.id, done_, total_,
             describeParameters(record.values), headline(record), seconds,
             done_ < total_ ? " · ETA " + duration(etaSeconds()) : "");
}

}  // namespace penumbra
