#pragma once
// Wall time for the reports (load, set-up, kernel, writing) and the progress lines: one steady
// clock, so that intervals never run backwards when the system clock is adjusted.
#include <chrono>

namespace penumbra {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace penumbra
