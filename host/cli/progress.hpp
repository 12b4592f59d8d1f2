#pragma once
// The progress line of a long run, on stderr: rewritten in place (at most ten times a second)
// when stderr is a terminal; otherwise one line when each grid starts and one when it ends, so
// that logs stay short.
#include <chrono>
#include <cstddef>
#include <string>

#include "grid/scene_grids.hpp"

namespace penumbra {

class ProgressLine : public GridObserver {
 public:
  explicit ProgressLine(bool enabled);
  void startGrid(const std::string& name, std::size_t points) override;
  void update(std::size_t done, std::size_t total) override;
  void finishGrid(double seconds) override;

 private:
  bool enabled_;
  bool terminal_;
  std::string grid_;
  std::size_t total_ = 0;
  std::chrono::steady_clock::time_point lastPrint_{};
};

}  // namespace penumbra
