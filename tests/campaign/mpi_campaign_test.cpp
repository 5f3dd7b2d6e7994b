// The automatic batch of a campaign (issue 13, docs/scaling.md): one sample per message on few
// ranks, where the master's cost per message is far below a sample's; on many ranks enough
// outcomes per message that the master's cost per sample falls below a lumped sample's cost
// divided by the number of workers.
#include "campaign/mpi_campaign.hpp"

#include <gtest/gtest.h>

namespace pound {
namespace {

TEST(CampaignBatch, AutomaticGrowsWithTheRanksAndAGivenBatchIsKept) {
  EXPECT_EQ(campaign_batch(0, 1), 1);
  EXPECT_EQ(campaign_batch(0, 2), 1);
  EXPECT_EQ(campaign_batch(0, 64), 1);
  EXPECT_EQ(campaign_batch(0, 65), 2);
  EXPECT_EQ(campaign_batch(0, 1000), 16);
  EXPECT_EQ(campaign_batch(0, 1024), 16);
  EXPECT_EQ(campaign_batch(0, 100000), 32);  // at most 32: a worker holds 4 x 32 samples
  EXPECT_EQ(campaign_batch(5, 2), 5);
  EXPECT_EQ(campaign_batch(1, 4096), 1);
}

}  // namespace
}  // namespace pound
