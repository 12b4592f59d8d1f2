#pragma once
// The progress of `penumbra sweep` on stderr: on a terminal one bar rewritten in place (cases
// done, time per case, ETA); in a log one line per finished case with its first grid's Eavg and
// U0, so that a batch job's log reads as a table.
#include <chrono>
#include <cstddef>

#include "study/sweep_runner.hpp"

namespace penumbra {

class SweepProgress : public SweepObserver {
 public:
  explicit SweepProgress(bool enabled);
  void planned(std::size_t toCompute, std::size_t finished) override;
  void caseStarted(const PlannedCase& c) override;
  void caseFinished(const CaseRecord& record, double seconds) override;

 private:
  void drawBar(const std::string& current) const;
  double etaSeconds() const;

  bool enabled_;
  bool terminal_;
  std::size_t total_ = 0;
  std::size_t done_ = 0;
  std::chrono::steady_clock::time_point start_{};
};

}  // namespace penumbra
