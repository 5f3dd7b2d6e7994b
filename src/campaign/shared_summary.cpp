#include "campaign/shared_summary.hpp"

#include <sys/resource.h>

#include "core/error.hpp"

namespace pound {

CampaignSummary share_summary(const CampaignSummary& master, int batch, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  long buf[4] = {master.total, master.done, master.failed, master.interrupted ? 1L : 0L};
  MPI_Bcast(buf, 4, MPI_LONG, 0, comm);
  CampaignSummary sum;
  sum.total = buf[0];
  sum.done = buf[1];
  sum.failed = buf[2];
  sum.interrupted = buf[3] != 0;
  sum.loop_seconds = master.loop_seconds;
  sum.busy_seconds = master.busy_seconds;
  sum.messages = master.messages;
  sum.batch = batch;
  if (rank == 0) sum.stop_reason = master.stop_reason;
  return sum;
}

void throw_on_every_rank(const std::string& error, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  int length = static_cast<int>(error.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, comm);
  if (length) throw InputError(rank == 0 ? error : std::string("(reported by rank 0)"));
}

double peak_memory_mb(MPI_Comm comm) {
  struct rusage ru {};
  getrusage(RUSAGE_SELF, &ru);
  double mb = static_cast<double>(ru.ru_maxrss) / 1024.0, max_mb = 0.0;  // ru_maxrss: kB
  MPI_Allreduce(&mb, &max_mb, 1, MPI_DOUBLE, MPI_MAX, comm);
  return max_mb;
}

}  // namespace pound
