#include "campaign/mpi_campaign.hpp"

#include <algorithm>
#include <ctime>
#include <string>

#include "campaign/campaign_master.hpp"
#include "campaign/campaign_worker.hpp"
#include "campaign/final_result.hpp"
#include "campaign/result_file.hpp"
#include "campaign/shared_summary.hpp"

namespace pound {
namespace {

std::string now_text() {
  char buf[64];
  const std::time_t t = std::time(nullptr);
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%S%z", std::localtime(&t));
  return buf;
}

}  // namespace

int campaign_batch(int batch, int ranks) {
  if (batch > 0) return batch;
  return std::min(32, std::max(1, (ranks + 63) / 64));
}

CampaignSummary run_campaign(const CampaignStudy& st, const CampaignRunOptions& opt,
                             MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  RunInfo info;
  info.ranks = size;
  info.start_time = now_text();
  const int batch = campaign_batch(st.batch, size);
  CampaignSummary master;
  std::string error;
  if (rank == 0) {
    try {
      master = run_master(st, opt, comm, size, batch);
    } catch (const std::exception& e) {
      error = e.what();
    }
  } else {
    run_worker(st, opt, comm, rank, batch);
  }
  // The outcome (and any master error) on every rank.
  CampaignSummary sum = share_summary(master, batch, comm);
  throw_on_every_rank(error, comm);
  if (rank == 0 && sum.done == sum.total && sum.stop_reason.empty() && opt.write_result) {
    info.end_time = now_text();
    error = write_final_result(st, opt, info, sum);
  }
  // A result file that cannot be written is a stop (the system's reason) or an error (any
  // other) on every rank, as above.
  throw_on_every_rank(error, comm);
  int interrupted = sum.interrupted ? 1 : 0;
  MPI_Bcast(&interrupted, 1, MPI_INT, 0, comm);
  sum.interrupted = interrupted != 0;
  sum.peak_rss_mb = peak_memory_mb(comm);
  MPI_Barrier(comm);
  return sum;
}

}  // namespace pound
