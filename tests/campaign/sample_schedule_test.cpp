// The master's schedule of samples (issue 13): samples handed out in order, skipping those a
// resumed run found done, duplicates recognised, memory in intervals rather than per sample.
#include "campaign/sample_schedule.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

namespace pound {
namespace {

TEST(SampleSchedule, HandsOutEverySampleOnceInOrderSkippingDoneOnes) {
  SampleSchedule s(10, 30);
  for (long id : {12L, 13L, 14L, 20L, 29L, 13L, 9L, 30L}) s.mark_done(id);
  EXPECT_EQ(s.intervals(), 3u);  // [12, 15), [20, 21), [29, 30); 13 twice, 9 and 30 outside
  std::vector<long> got;
  long id = 0;
  while (s.take(id)) got.push_back(id);
  const std::vector<long> want = {10, 11, 15, 16, 17, 18, 19, 21, 22, 23, 24, 25, 26, 27, 28};
  EXPECT_EQ(got, want);
  EXPECT_TRUE(s.exhausted());
  EXPECT_EQ(s.in_flight(), long(want.size()));
  EXPECT_TRUE(s.complete(16));
  EXPECT_FALSE(s.complete(16));  // a duplicate
  EXPECT_FALSE(s.complete(12));  // done before the run, never handed out
  EXPECT_EQ(s.in_flight(), long(want.size()) - 1);
}

TEST(SampleSchedule, ResumedJournalOfAMillionSamplesKeepsAFewIntervals) {
  // A journal in completion order: ids in increasing order except that 64 workers finish their
  // samples out of order, and 100 samples were in flight when the run was killed.
  const long n = 1000000;
  std::mt19937 gen(3);
  std::vector<long> order;
  for (long i = 0; i < n; ++i) order.push_back(i);
  for (long b = 0; b + 64 <= n; b += 64)
    std::shuffle(order.begin() + b, order.begin() + b + 64, gen);
  std::set<long> lost;
  while (lost.size() < 100) lost.insert(std::uniform_int_distribution<long>(0, n - 1)(gen));
  SampleSchedule s(0, n);
  long marked = 0;
  for (long id : order)
    if (!lost.count(id)) marked += s.mark_done(id);
  EXPECT_EQ(marked, n - 100);
  EXPECT_LE(s.intervals(), 101u);
  std::set<long> rerun;
  long id = 0;
  while (s.take(id)) rerun.insert(id);
  EXPECT_EQ(rerun, lost);
}

}  // namespace
}  // namespace pound
