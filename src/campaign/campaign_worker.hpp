#pragma once
// A worker rank of a campaign: keeps kRequestsInFlight requests at the master, simulates the
// sample ids it is given, and returns their journal records with its next request, one at a
// time or `batch` at a time (sooner when its queue runs dry); a stop from the master ends it
// (campaign_messages.hpp has the protocol).
#include <mpi.h>

#include "campaign/campaign_run.hpp"
#include "campaign/campaign_study.hpp"

namespace pound {

/// Runs until the master has answered every request with a stop, then tells it so.
void run_worker(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm, int rank,
                int batch);

}  // namespace pound
