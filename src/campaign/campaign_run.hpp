#pragma once
// What one campaign run is asked to do (CampaignRunOptions) and what it reports
// (CampaignSummary); run_campaign (mpi_campaign.hpp) takes the one and returns the other.
#include <functional>
#include <string>

#include "campaign/sample.hpp"

namespace pound {

/// Ranks up to which the master also simulates by default.
inline constexpr int kMasterSimulatesUpTo = 8;

struct CampaignRunOptions {
  std::string out;           ///< result file RUN.h5 (journal: RUN.h5.journal)
  bool resume = false;       ///< continue from the journal
  bool progress = true;      ///< progress lines on stderr (master)
  std::string command_line;  ///< how to resume, for the interruption message
  /// Whether the master simulates samples between requests: by default only on up to
  /// kMasterSimulatesUpTo ranks (a laptop's cores all busy); on more, it only schedules and
  /// journals, so that its own samples never delay the replies to hundreds of workers.
  enum class MasterWork { automatic, simulate, schedule_only } master_work = MasterWork::automatic;
  /// Replaces SampleRunner::run on every rank (benchmarks of the master: an outcome at once).
  std::function<SampleOutcome(long id)> simulate;
  /// Build RUN.h5 from the journal at the end (benchmarks of the master's loop: false, and the
  /// journal is left for the caller).
  bool write_result = true;
};

struct CampaignSummary {
  long total = 0, done = 0, failed = 0;
  bool interrupted = false;  ///< stopped by SIGTERM/SIGUSR1/SIGINT or a failed write
  /// Rank 0: why the campaign stopped other than by a signal, a write that failed for want of
  /// space (disk full, quota, file size limit: ENOSPC, EDQUOT, EFBIG) with the system's reason;
  /// the journal is kept, as on SIGTERM. Any other failed write is an error (run_campaign
  /// throws), the journal kept all the same.
  std::string stop_reason;
  double peak_rss_mb = 0.0;   ///< largest peak resident memory of any rank [MB]
  double loop_seconds = 0.0;  ///< master: time in the scheduling loop, without the file [s]
  /// master: time spent serving workers' messages (receiving, journalling, replying), without
  /// waiting for them and without its own samples [s]
  double busy_seconds = 0.0;
  long messages = 0;  ///< master: messages with outcomes received from workers
  int batch = 1;      ///< the batch used
};

}  // namespace pound
