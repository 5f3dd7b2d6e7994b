#pragma once
// The master's progress line on stderr, at most every two seconds and once at the end:
// "campaign: 120/960 samples done, 0 failed, 84.10 samples/s, ~10 s left".
#include <chrono>

#include "campaign/campaign_run.hpp"

namespace pound {

class ProgressLine {
 public:
  /// `enabled`: false prints nothing (--quiet). `done_at_start`: samples a resumed run found in
  /// its journal (not counted in the rate).
  ProgressLine(bool enabled, long done_at_start);
  /// Prints the line when two seconds have passed since the last one, or when `final`.
  void report(const CampaignSummary& sum, bool final);
  /// Seconds since construction.
  double elapsed_seconds() const;

 private:
  bool enabled_;
  long at_start_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace pound
