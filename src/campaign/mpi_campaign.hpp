#pragma once
// Runs a campaign over MPI ranks: rank 0 (the master) hands out sample ids on request, keeps
// the journal and simulates samples itself between requests; the other ranks simulate the
// samples they are given. MPI lives only here: samples are pure functions of (study, id).
#include <mpi.h>

#include <functional>
#include <string>

#include "campaign/campaign_study.hpp"
#include "campaign/sample.hpp"

namespace pound {

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

/// Ranks up to which the master also simulates by default.
inline constexpr int kMasterSimulatesUpTo = 8;

/// The batch a run uses: CampaignStudy::batch, or for 0 (automatic) 1 on up to 64 ranks, where
/// the master's cost per message is far below a sample's, and ceil(ranks / 64) (at most 32)
/// beyond, so that one master keeps thousands of workers busy (docs/scaling.md).
int campaign_batch(int batch, int ranks);

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

/// Collective over `comm`. Returns the same summary on every rank. Throws InputError on every
/// rank for journal/output problems (after telling the workers to stop), a journal or result
/// file that cannot be written for another reason than space included (read-only file system,
/// permission, I/O error: the message names the file and the system's reason).
CampaignSummary run_campaign(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm);

/// Installs handlers so that SIGTERM, SIGUSR1 and SIGINT request a clean stop, and ignores
/// SIGXFSZ (a file size limit is then a failed write). Call it before MPI_Init: a request that
/// comes while the ranks start is then kept and honoured once the campaign runs.
void install_stop_handlers();
/// True once a stop signal came (SIGTERM, SIGUSR1, SIGINT). A failed write of the journal
/// stops only the run it happened in, not a later run_campaign of the same process.
bool stop_requested();

}  // namespace pound
