#pragma once
// The master rank (0) of a campaign: answers the workers' requests with sample ids, journals
// the records they return (one write and flush per message) and books each by its id and
// status, simulates samples itself between requests (on up to kMasterSimulatesUpTo ranks), and
// on a stop request or a failed journal write stops handing out work and answers every request
// with a stop until the workers are done.
#include <mpi.h>

#include "campaign/campaign_run.hpp"
#include "campaign/campaign_study.hpp"

namespace pound {

/// Runs the master's side of the campaign over `comm` (of `size` ranks). A journal that cannot
/// be written for want of space is a stop (the summary says interrupted, with the reason); any
/// other failure throws (write_failure.hpp), once every worker has been told to stop.
CampaignSummary run_master(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm,
                           int size, int batch);

}  // namespace pound
