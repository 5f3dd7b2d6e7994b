#include "campaign/campaign_progress.hpp"

#include <cstdio>

namespace pound {

ProgressLine::ProgressLine(bool enabled, long done_at_start)
    : enabled_(enabled),
      at_start_(done_at_start),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void ProgressLine::report(const CampaignSummary& sum, bool final) {
  const auto t = std::chrono::steady_clock::now();
  if (!enabled_ || (!final && t - last_ < std::chrono::seconds(2))) return;
  last_ = t;
  const double el = std::chrono::duration<double>(t - start_).count();
  const double rate = el > 0 ? (sum.done - at_start_) / el : 0.0;
  const double left = rate > 0 ? (sum.total - sum.done) / rate : 0.0;
  std::fprintf(stderr, "campaign: %ld/%ld samples done, %ld failed, %.2f samples/s, ~%.0f s left\n",
               sum.done, sum.total, sum.failed, rate, left);
}

double ProgressLine::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

}  // namespace pound
