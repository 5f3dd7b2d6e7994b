#pragma once
// Runs a campaign over MPI ranks: rank 0 (the master, campaign_master.hpp) hands out sample ids
// on request, keeps the journal and simulates samples itself between requests; the other ranks
// (campaign_worker.hpp) simulate the samples they are given. MPI lives only in these files:
// samples are pure functions of (study, id).
#include <mpi.h>

#include "campaign/campaign_run.hpp"
#include "campaign/campaign_study.hpp"
#include "campaign/stop_signals.hpp"

namespace pound {

/// The batch a run uses: CampaignStudy::batch, or for 0 (automatic) 1 on up to 64 ranks, where
/// the master's cost per message is far below a sample's, and ceil(ranks / 64) (at most 32)
/// beyond, so that one master keeps thousands of workers busy (docs/scaling.md).
int campaign_batch(int batch, int ranks);

/// Collective over `comm`. Returns the same summary on every rank. Throws InputError on every
/// rank for journal/output problems (after telling the workers to stop), a journal or result
/// file that cannot be written for another reason than space included (read-only file system,
/// permission, I/O error: the message names the file and the system's reason).
CampaignSummary run_campaign(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm);

}  // namespace pound
