#pragma once
// The progress line of a render on stderr: shown only once a view has taken more than a second
// (short renders stay quiet), rewritten in place on a terminal at most ten times a second, with
// the rows done and the time left.
#include <chrono>
#include <string>

namespace penumbra {

class RenderProgress {
 public:
  RenderProgress(bool enabled, std::string view, int rows);
  void update(double fraction);  // in [0, 1]
  void finish();

 private:
  bool enabled_, terminal_;
  std::string view_;
  int rows_;
  std::chrono::steady_clock::time_point start_, lastPrint_{};
  bool shown_ = false;
};

}  // namespace penumbra
