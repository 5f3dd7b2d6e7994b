#pragma once
// The end of a finished campaign (rank 0): RUN.h5 built from the complete journal, through a
// temporary file renamed into place, and the journal removed.
#include <string>

#include "campaign/campaign_run.hpp"
#include "campaign/campaign_study.hpp"
#include "campaign/result_file.hpp"

namespace pound {

/// Writes opt.out from opt.out.journal (the host is added to `info`) and removes the journal.
/// A write that fails for want of space (disk full, quota, file size limit) stops the campaign
/// as SIGTERM does: `sum` is marked interrupted with the reason, the temporary removed, the
/// journal kept for `--resume`, and "" returned. Any other failure returns its message (the
/// journal stays too).
std::string write_final_result(const CampaignStudy& st, const CampaignRunOptions& opt, RunInfo info,
                               CampaignSummary& sum);

}  // namespace pound
