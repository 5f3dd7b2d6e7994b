#pragma once
// What rank 0 knows at the end of a campaign, shared with every rank (collective calls over
// the campaign's communicator): the counts and whether it stopped, an error to throw on every
// rank, and the largest peak memory of any rank.
#include <mpi.h>

#include <string>

#include "campaign/campaign_run.hpp"

namespace pound {

/// The master's counts and stop flag on every rank; the master's own timings, message count
/// and stop reason stay on rank 0 (0 and "" elsewhere); `batch` on every rank.
CampaignSummary share_summary(const CampaignSummary& master, int batch, MPI_Comm comm);

/// Throws InputError on every rank when rank 0's `error` is not empty (rank 0: the error,
/// the others: "(reported by rank 0)").
void throw_on_every_rank(const std::string& error, MPI_Comm comm);

/// The largest peak resident memory of any rank [MB] (ru_maxrss).
double peak_memory_mb(MPI_Comm comm);

}  // namespace pound
