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
};

/// Ranks up to which the master also simulates by default.
inline constexpr int kMasterSimulatesUpTo = 8;

struct CampaignSummary {
  long total = 0, done = 0, failed = 0;
  bool interrupted = false;  ///< stopped by SIGTERM/SIGUSR1/SIGINT or a failed write
  /// Rank 0: why the campaign stopped other than by a signal, a write that failed in the
  /// system (disk full, file size limit) with its reason; the journal is kept, as on SIGTERM.
  std::string stop_reason;
  double peak_rss_mb = 0.0;   ///< largest peak resident memory of any rank [MB]
  double loop_seconds = 0.0;  ///< master: time in the scheduling loop, without the file [s]
};

/// Collective over `comm`. Returns the same summary on every rank. Throws InputError on the
/// master for journal/output problems (after telling the workers to stop).
CampaignSummary run_campaign(const CampaignStudy& st, const CampaignRunOptions& opt, MPI_Comm comm);

/// Installs handlers so that SIGTERM, SIGUSR1 and SIGINT request a clean stop, and ignores
/// SIGXFSZ (a file size limit is then a failed write). Call it before MPI_Init: a request that
/// comes while the ranks start is then kept and honoured once the campaign runs.
void install_stop_handlers();
/// True once a stop was requested.
bool stop_requested();

}  // namespace pound
